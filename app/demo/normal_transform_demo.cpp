// raystep demo normal-transform: why stage 5 takes normals to the world by M^-T and not by M.

#include <glm/geometric.hpp>

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"
#include "renderer/tile_renderer.h"

namespace raystep {

namespace {

// The mistake this demo shows: treating a normal like any other direction. M stretches a
// surface's tangents and its normal alike, so under a non-uniform scale the normal leans
// towards the stretched axis, away from perpendicular. Only M^-T keeps n . t = 0 for every
// tangent t (normal_to_world).
Vec3 normal_by_m(const Transform& transform, const Vec3& object_normal) {
    return glm::normalize(Vec3(transform.matrix * Vec4(object_normal, 0.0)));
}

using NormalToWorld = Vec3 (*)(const Transform&, const Vec3&);

// The normal view of the scene, the normals of ellipsoids taken to the world by `to_world`:
// every other primitive, and where the ray meets it, are the renderer's.
Image normal_image(const RenderScene& render_scene, NormalToWorld to_world) {
    const Scene& scene = *render_scene.scene;
    const PixelFunction pixel = [&](int i, int j) {
        const Ray ray = camera_ray(render_scene, i, j);
        const std::optional<PrimitiveHit> hit = scene_closest_hit(render_scene, ray, nullptr);
        if (!hit) return Color(0.0);
        Vec3 normal = hit->hit.normal;
        const Instance* instance = instance_of(render_scene, hit->kind, hit->index);
        if (hit->kind == PrimitiveKind::sphere && instance && instance->transform) {
            // Stage 5's recipe up to the normal: the sphere's own normal where the object-frame
            // ray meets it, then `to_world`
            const std::optional<Hit> object_hit = intersect_sphere(
                ray_to_object(*instance->transform, ray), scene.spheres[hit->index].shape);
            if (object_hit) normal = to_world(*instance->transform, object_hit->normal);
        }
        return 0.5 * (normal + Vec3(1.0));
    };
    return render_pixels(scene.width, scene.height, pixel, 0);
}

}  // namespace

DemoFigure normal_transform_demo(const DemoSize& size) {
    // A lentil and a cigar, unit spheres under non-uniform scales (stage 5's ellipsoids.test has
    // more, too small for half an image). By M the lentil's face takes on its rim's colours.
    const PanelSize panel = panel_size(size, 2, false);
    const Scene scene = load_demo_scene("demos/normal-transform.test", panel);
    const RenderScene render_scene = prepare_render_scene(scene);

    DemoFigure figure;
    figure.title = "Normals under a non-uniform scale, as colour (n + 1) / 2";
    figure.panels.push_back(
        {"M N (as if a direction): wrong", normal_image(render_scene, normal_by_m)});
    figure.panels.push_back(
        {"M^-T N (normal_to_world): right", normal_image(render_scene, normal_to_world)});
    return figure;
}

}  // namespace raystep
