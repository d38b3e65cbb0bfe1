// The demos of how a surface is lit and seen: normals under a transform (stage 5), where a
// shadow ray starts (stage 6), and glass (stage 9).

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"
#include "renderer/tile_renderer.h"

namespace raystep {

// raystep demo normal-transform: why stage 5 takes normals to the world by M^-T and not by M.

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

// raystep demo shadow-acne: where a shadow ray starts, and what a fixed epsilon gets wrong.

namespace {

// A pixel is in false shadow when it is this much darker than under the error bound. Lit and
// shadowed differ by the light's whole term (several units at this grazing light), while the
// rules change nothing else: any threshold well inside that gap counts the same pixels.
constexpr double kShadowStep = 0.05;

struct OffsetPanel {
    RayOffset offset;
    const char* label;
};

Image shaded(Scene scene, const RayOffset& offset) {
    scene.ray_offset = offset;
    RenderOptions options;
    options.view = View::shaded;
    return render_image(prepare_render_scene(scene), options);
}

// Pixels darker than in `truth` by more than kShadowStep in any channel.
std::size_t false_shadow_pixels(const Image& image, const Image& truth) {
    std::size_t count = 0;
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            const Color drop = truth.at(i, j) - image.at(i, j);
            if (drop.r > kShadowStep || drop.g > kShadowStep || drop.b > kShadowStep) ++count;
        }
    }
    return count;
}

}  // namespace

DemoFigure shadow_acne_demo(const DemoSize& size) {
    // Stage 6's acne scene at scale 1e4, where hit points carry rounding errors near 1e-8 and a
    // light grazes the floor at 3 degrees. `raystep bench --epsilon` measures that the error bound
    // gets every pixel of it right (docs/stage6.md, "Measuring acne"), so the pixels that another
    // rule makes darker are its acne. Along the ray, epsilon = 1e-12 still has acne there, and
    // 1e-3 is inside the range (1e-8 to 1e-1) that has neither acne nor leaks.
    const PanelSize panel = panel_size(size, 4, false);
    const Scene scene = load_demo_scene("stage6/acne-scale-1e4.test", panel);
    const Image truth = shaded(scene, {OffsetRule::error_bound, 0.0});
    const OffsetPanel fixed[] = {
        {{OffsetRule::along_ray, 0.0}, "epsilon = 0"},
        {{OffsetRule::along_ray, 1e-12}, "epsilon = 1e-12 along the ray"},
        {{OffsetRule::along_ray, 1e-3}, "epsilon = 1e-3 along the ray"},
    };

    DemoFigure figure;
    figure.title =
        "Shadow acne against epsilon: a sphere and a slab at scale 1e4, light at 3 degrees";
    for (const OffsetPanel& p : fixed) {
        Image image = shaded(scene, p.offset);
        const std::size_t acne = false_shadow_pixels(image, truth);
        figure.panels.push_back({std::string(p.label) + ": " + thousands(acne) +
                                     (acne == 1 ? " pixel" : " pixels") + " of acne",
                                 std::move(image)});
    }
    figure.panels.push_back({"error bound, no epsilon: no acne", truth});
    return figure;
}

// raystep demo refraction: a glass cube at four indices, and where total internal reflection sets
// in.

namespace {

struct IndexPanel {
    double index;
    const char* medium;
};

// Every transmitting material of the scene made of index `index`.
Image with_index(Scene scene, double index) {
    for (Material& material : scene.materials) {
        if (material.transmission != Color(0.0)) material.index = index;
    }
    return render_image(prepare_render_scene(scene), RenderOptions{});
}

// "n = 1.5 (glass): critical angle 41.8 deg"; at n = 1 there is none.
std::string index_caption(const IndexPanel& p) {
    char text[96];
    if (p.index > 1.0) {
        std::snprintf(text, sizeof text, "n = %g (%s): critical angle %.1f deg", p.index, p.medium,
                      glm::degrees(std::asin(1.0 / p.index)));
    } else {
        std::snprintf(text, sizeof text, "n = %g (%s): no bending", p.index, p.medium);
    }
    return text;
}

}  // namespace

DemoFigure refraction_demo(const DemoSize& size) {
    // scenes/demos/glass-cube.test: a clear glass cube on a checkered floor, seen from above.
    // Light entering the top face at theta_t from the vertical inside meets a side face at 90
    // degrees minus theta_t; beyond the critical angle asin(1/n) it is reflected whole, and that
    // face shows the cube's inside instead of the floor behind. At n = 1 nothing bends and the
    // cube vanishes; at 1.33 light that entered within 61 degrees of the vertical is reflected
    // (the camera looks down at 56 degrees from it); at 1.5 and 2.4 all of it is.
    const PanelSize panel = panel_size(size, 4, false);
    const Scene scene = load_demo_scene("demos/glass-cube.test", panel);
    const IndexPanel panels[] = {{1.0, "air"}, {1.33, "water"}, {1.5, "glass"}, {2.4, "diamond"}};

    DemoFigure figure;
    figure.title = "Refraction and total internal reflection: a cube of index n";
    for (const IndexPanel& p : panels) {
        figure.panels.push_back({index_caption(p), with_index(scene, p.index)});
    }
    return figure;
}

}  // namespace raystep
