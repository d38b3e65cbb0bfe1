#include "core/render/render_scene.h"

#include <stdexcept>

#include "core/render/render_plan.h"
#include "core/scene/scene_features.h"

namespace raystep {

RenderScene prepare_render_scene(const Scene& scene) {
    if (scene_features(scene).uses_transforms()) {
        throw std::runtime_error(scene.path +
                                 ": this scene places objects with translate, rotate or scale, "
                                 "which needs stage 5 (transforms), not yet part of raystep");
    }

    RenderScene render_scene;
    render_scene.scene = &scene;

    const CameraSpec& c = scene.camera;
    if (c.ortho) {
        render_scene.camera =
            make_orthographic_camera(c.lookfrom, c.lookat, c.up, c.ortho->left, c.ortho->right,
                                     c.ortho->bottom, c.ortho->top, scene.width, scene.height);
    } else {
        render_scene.camera = make_perspective_camera(c.lookfrom, c.lookat, c.up, c.fovy_degrees,
                                                      scene.width, scene.height);
    }

    PrimitiveList& list = render_scene.primitives;
    list.spheres.reserve(scene.spheres.size());
    for (const SceneSphere& s : scene.spheres)
        list.spheres.push_back(s.shape);
    list.triangles.reserve(scene.triangles.size());
    for (const SceneTriangle& t : scene.triangles)
        list.triangles.push_back(t.shape);
    list.planes.reserve(scene.planes.size());
    for (const ScenePlane& p : scene.planes)
        list.planes.push_back(p.shape);

    if (uses_bvh(scene_features(scene))) {
        render_scene.bvh.emplace(list, BvhSplit::sah);
        render_scene.planes.planes = list.planes;
    }
    return render_scene;
}

std::optional<PrimitiveHit> scene_closest_hit(const RenderScene& render_scene, const Ray& ray,
                                              TraversalStats* stats) {
    const PrimitiveList& list = render_scene.primitives;
    if (!render_scene.bvh) {
        if (stats)
            stats->primitive_tests +=
                list.spheres.size() + list.triangles.size() + list.planes.size();
        return closest_hit(ray, list);
    }
    std::optional<PrimitiveHit> best = render_scene.bvh->closest_hit(ray, stats);
    // The planes come after spheres and triangles in closest_hit's order, so on a tie the BVH's
    // hit stays, and a plane must be strictly nearer.
    Ray nearer = ray;
    if (best) nearer.t_max = best->hit.t;
    const std::optional<PrimitiveHit> plane = closest_hit(nearer, render_scene.planes);
    if (stats) stats->primitive_tests += list.planes.size();
    if (plane && (!best || comes_before(*plane, *best))) best = plane;
    return best;
}

Ray camera_ray(const RenderScene& render_scene, int i, int j) {
    if (const auto* perspective = std::get_if<PerspectiveCamera>(&render_scene.camera)) {
        return perspective_ray(*perspective, i, j);
    }
    return orthographic_ray(std::get<OrthographicCamera>(render_scene.camera), i, j);
}

const ObjectAttributes& attributes_of(const RenderScene& render_scene, PrimitiveKind kind,
                                      std::size_t index) {
    const Scene& scene = *render_scene.scene;
    switch (kind) {
        case PrimitiveKind::sphere:
            return scene.spheres.at(index).attributes;
        case PrimitiveKind::triangle:
            return scene.triangles.at(index).attributes;
        case PrimitiveKind::plane:
            return scene.planes.at(index).attributes;
    }
    throw std::logic_error("attributes_of: unknown primitive kind");
}

const char* kind_name(PrimitiveKind kind) {
    switch (kind) {
        case PrimitiveKind::sphere:
            return "sphere";
        case PrimitiveKind::triangle:
            return "triangle";
        case PrimitiveKind::plane:
            return "plane";
    }
    return "primitive";
}

}  // namespace raystep
