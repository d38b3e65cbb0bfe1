#include "app/render/render_scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "app/render/render_plan.h"
#include "base/scene/scene_features.h"

namespace raystep {

namespace {

// The transform of a node, composed by stage 5 the first time an object under it is met.
const Transform& transform_of(const Scene& scene, std::uint32_t node,
                              std::unordered_map<std::uint32_t, Transform>& transforms) {
    auto found = transforms.find(node);
    if (found == transforms.end()) {
        found = transforms.emplace(node, compose(transform_ops(scene, node))).first;
    }
    return found->second;
}

double inverse_residual(const Transform& transform) {
    const Mat4 product = transform.inverse * transform.matrix;
    double largest = 0.0;
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            const double expected = row == column ? 1.0 : 0.0;
            largest = std::max(largest, std::abs(product[column][row] - expected));
        }
    }
    return largest;
}

void gather_primitives(const Scene& scene, RenderScene& render_scene) {
    PrimitiveList& list = render_scene.primitives;
    for (std::size_t k = 0; k < scene.spheres.size(); ++k) {
        const SceneSphere& s = scene.spheres[k];
        if (s.attributes.transform == 0) {
            render_scene.sphere_slot.push_back(list.spheres.size());
            list.spheres.push_back(s.shape);
            render_scene.sphere_index.push_back(k);
            continue;
        }
        render_scene.sphere_slot.push_back(render_scene.transformed_spheres.size());
        const Transform& t = transform_of(scene, s.attributes.transform, render_scene.transforms);
        render_scene.transformed_spheres.push_back({s.shape, t, k, inverse_residual(t)});
    }
    // Flat primitives stay flat under any transform: moved into the world once, they need no
    // matrix per ray and go into the BVH with the rest.
    list.triangles.reserve(scene.triangles.size());
    for (const SceneTriangle& t : scene.triangles) {
        if (t.attributes.transform == 0) {
            list.triangles.push_back(t.shape);
            continue;
        }
        const Transform& m = transform_of(scene, t.attributes.transform, render_scene.transforms);
        list.triangles.push_back({point_to_world(m, t.shape.p0), point_to_world(m, t.shape.p1),
                                  point_to_world(m, t.shape.p2)});
    }
    list.planes.reserve(scene.planes.size());
    for (const ScenePlane& p : scene.planes) {
        if (p.attributes.transform == 0) {
            list.planes.push_back(p.shape);
            continue;
        }
        const Transform& m = transform_of(scene, p.attributes.transform, render_scene.transforms);
        list.planes.push_back(
            {point_to_world(m, p.shape.point), normal_to_world(m, p.shape.normal)});
    }
}

// `candidate` replaces `best` when closest_hit would have picked it.
void keep_nearer(std::optional<PrimitiveHit>& best, const std::optional<PrimitiveHit>& candidate) {
    if (candidate && (!best || comes_before(*candidate, *best))) best = candidate;
}

// The ray cut at the best hit so far: nothing beyond it can win.
Ray cut_at(const Ray& ray, const std::optional<PrimitiveHit>& best) {
    Ray cut = ray;
    if (best) cut.t_max = best->hit.t;
    return cut;
}

std::optional<PrimitiveHit> transformed_sphere_hit(const TransformedSphere& s, const Ray& ray) {
    const std::optional<Hit> hit = intersect_transformed_sphere(ray, s.sphere, s.transform);
    if (!hit) return std::nullopt;
    return PrimitiveHit{*hit, PrimitiveKind::sphere, s.index};
}

}  // namespace

SceneCamera make_scene_camera(const Scene& scene) {
    const CameraSpec& c = scene.camera;
    if (c.ortho) {
        return make_orthographic_camera(c.lookfrom, c.lookat, c.up, c.ortho->left, c.ortho->right,
                                        c.ortho->bottom, c.ortho->top, scene.width, scene.height);
    }
    return make_perspective_camera(c.lookfrom, c.lookat, c.up, c.fovy_degrees, scene.width,
                                   scene.height);
}

RenderScene prepare_render_scene(const Scene& scene) {
    RenderScene render_scene;
    render_scene.scene = &scene;
    render_scene.camera = make_scene_camera(scene);
    gather_primitives(scene, render_scene);
    const SceneFeatures features = scene_features(scene);
    if (uses_bvh(features)) {
        render_scene.bvh.emplace(render_scene.primitives, BvhSplit::sah);
        render_scene.planes.planes = render_scene.primitives.planes;
    }
    render_scene.ray_offset = scene.ray_offset;
    render_scene.bounces = features.uses_reflection() ? scene.max_depth : 0;
    return render_scene;
}

std::optional<PrimitiveHit> scene_closest_hit(const RenderScene& render_scene, const Ray& ray,
                                              TraversalStats* stats) {
    const PrimitiveList& list = render_scene.primitives;
    std::optional<PrimitiveHit> best;
    if (render_scene.bvh) {
        best = render_scene.bvh->closest_hit(ray, stats);
    } else {
        best = closest_hit(ray, list);
        if (stats) stats->primitive_tests += list.spheres.size() + list.triangles.size();
    }
    if (best && best->kind == PrimitiveKind::sphere) {
        best->index = render_scene.sphere_index[best->index];
    }
    if (render_scene.bvh) {
        keep_nearer(best, closest_hit(cut_at(ray, best), render_scene.planes));
    }
    for (const TransformedSphere& s : render_scene.transformed_spheres) {
        keep_nearer(best, transformed_sphere_hit(s, cut_at(ray, best)));
    }
    if (stats)
        stats->primitive_tests += list.planes.size() + render_scene.transformed_spheres.size();
    return best;
}

bool scene_occluded(const RenderScene& render_scene, const Ray& ray) {
    if (render_scene.bvh) {
        if (render_scene.bvh->occluded(ray, nullptr)) return true;
        if (closest_hit(ray, render_scene.planes)) return true;
    } else if (closest_hit(ray, render_scene.primitives)) {
        return true;
    }
    for (const TransformedSphere& s : render_scene.transformed_spheres) {
        if (intersect_transformed_sphere(ray, s.sphere, s.transform)) return true;
    }
    return false;
}

Ray camera_ray(const SceneCamera& camera, int i, int j) {
    if (const auto* perspective = std::get_if<PerspectiveCamera>(&camera)) {
        return perspective_ray(*perspective, i, j);
    }
    return orthographic_ray(std::get<OrthographicCamera>(camera), i, j);
}

Ray camera_ray(const RenderScene& render_scene, int i, int j) {
    Ray ray = camera_ray(render_scene.camera, i, j);
    ray.t_min = std::max(ray.t_min, render_scene.camera_t_min);
    ray.t_max = std::min(ray.t_max, render_scene.camera_t_max);
    return ray;
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
