// The demos of stages 2 and 3: what the cameras make, barycentric coordinates, and rays that
// slip between the triangles of a closed mesh.

#include <stdexcept>
#include <string_view>

#include <glm/geometric.hpp>

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"
#include "renderer/tile_renderer.h"

namespace raystep {

// raystep demo ray-directions: what stage 2's cameras make, before anything is hit.

DemoFigure ray_directions_demo(const DemoSize& size) {
    // The two cameras of stage 2's scenes. The rays view colours a direction d as (d + 1) / 2:
    // red grows to the right, green upwards, and -z (straight ahead) is (0.5, 0.5, 0).
    const PanelSize panel = panel_size(size, 2, false);
    DemoFigure figure;
    figure.title = "Ray directions as colour: (d + 1) / 2, red = x, green = y, blue = z";
    figure.panels.push_back(view_panel("stage2/perspective-wide.test", panel, View::rays,
                                       "perspective: a direction per pixel"));
    figure.panels.push_back(view_panel("stage2/orthographic.test", panel, View::rays,
                                       "orthographic: one direction, one colour"));
    return figure;
}

// raystep demo barycentrics: the beta and gamma that stage 3's triangle tests return.

DemoFigure barycentrics_demo(const DemoSize& size) {
    // Stage 3's scenes: each triangle runs from red at p0 through green at p1 to blue at p2, so
    // shared edges show as seams, and a pixel of background on a seam would be a leak.
    const PanelSize panel = panel_size(size, 2, false);
    DemoFigure figure;
    figure.title = "Barycentric coordinates as colour: RGB = (1 - beta - gamma, beta, gamma)";
    figure.panels.push_back(view_panel("stage3/triangle-fan.test", panel, View::barycentric,
                                       "eight triangles around one vertex"));
    figure.panels.push_back(view_panel("stage3/quad-oblique.test", panel, View::barycentric,
                                       "a square of two triangles, seen obliquely"));
    return figure;
}

// raystep demo watertight: rays that slip between the triangles of a closed mesh.

namespace {

// What a ray's first hit on a closed mesh, seen from outside, says about it.
enum class FirstHit { none, front, back };

using TriangleTest = std::optional<Hit> (*)(const Ray&, const Triangle&);

const Color kBackground(0.05, 0.05, 0.1);
const Color kLeak(1.0, 0.0, 1.0);  // magenta: a colour no shading of the grey mesh makes

// The first hit among all the triangles by `test`, and the cosine between its normal and the
// ray's direction. Every triangle, every pixel: at 320 triangles cheaper than building a
// structure, and it keeps stage 4 out of a stage 3 demo.
FirstHit first_hit(const std::vector<SceneTriangle>& triangles, const Ray& ray, TriangleTest test,
                   double& cosine) {
    Ray nearer = ray;
    FirstHit first = FirstHit::none;
    for (const SceneTriangle& triangle : triangles) {
        const std::optional<Hit> hit = test(nearer, triangle.shape);
        if (!hit) continue;
        nearer.t_max = hit->t;
        cosine = glm::dot(hit->normal, glm::normalize(ray.direction));
        // The mesh's triangles turn counterclockwise seen from outside: a normal facing the ray
        // is the outside
        first = cosine < 0.0 ? FirstHit::front : FirstHit::back;
    }
    return first;
}

// The mesh under one triangle test: grey by the angle it is seen at, its leaks magenta. Seen
// from outside, the first hit on a closed mesh is always on its outside; a first hit on the
// inside means the ray came in through a crack between two triangles.
struct LeakPanel {
    Image image;
    std::size_t leaks = 0;
};

LeakPanel leak_panel(const Scene& scene, const SceneCamera& camera, TriangleTest test) {
    const PixelFunction pixel = [&](int i, int j) {
        double cosine = 0.0;
        switch (first_hit(scene.triangles, camera_ray(camera, i, j), test, cosine)) {
            case FirstHit::none:
                return kBackground;
            case FirstHit::front:
                return Color(0.15 + 0.75 * -cosine);
            case FirstHit::back:
                break;
        }
        return kLeak;
    };
    LeakPanel panel{render_pixels(scene.width, scene.height, pixel, 0)};
    for (int j = 0; j < panel.image.height(); ++j) {
        for (int i = 0; i < panel.image.width(); ++i) {
            if (panel.image.at(i, j) == kLeak) ++panel.leaks;
        }
    }
    return panel;
}

std::string leak_caption(const std::string& method, std::size_t leaks) {
    return method + ": " + thousands(leaks) + (leaks == 1 ? " leaking pixel" : " leaking pixels");
}

struct NamedTriangleTest {
    std::string_view name;
    TriangleTest test;
};

// Stage 3's triangle tests, by their names in intersect.h.
constexpr NamedTriangleTest kTriangleTests[] = {
    {"intersect_triangle", intersect_triangle},
    {"intersect_triangle_halfspaces", intersect_triangle_halfspaces},
    {"intersect_triangle_projection", intersect_triangle_projection},
    {"intersect_triangle_cramer", intersect_triangle_cramer},
};

}  // namespace

DemoFigure watertight_demo(const DemoSize& size) {
    // scenes/demos/watertight.test: an icosphere of radius 1 around (1e14, 5e13, -7.5e13),
    // where doubles are 1/64 apart: the power of ten at which the half-space method leaks at
    // hundreds of pixels, enough to see on a projector, while the vertices still sit on a sphere
    // (ten times as far they snap to a grid an eighth of the radius wide). The counts at each
    // power of ten, and how to rerun them: docs/measurements/watertight-demo.md. Both tests are
    // stage 3's: intersect_triangle (the reference's is watertight; Woop, Benthin, Wald 2013) and
    // the lecture's half-space method, which finds the point on the plane first and so rounds it
    // to that 1/64.
    const PanelSize panel = panel_size(size, 2, false);
    const Scene scene = load_demo_scene("demos/watertight.test", panel);
    const SceneCamera camera = make_scene_camera(scene);

    const LeakPanel renderer = leak_panel(scene, camera, intersect_triangle);
    const LeakPanel halfspaces = leak_panel(scene, camera, intersect_triangle_halfspaces);
    DemoFigure figure;
    figure.title = "A closed mesh at 1e14 from the origin: rays through the cracks in magenta";
    figure.panels.push_back({leak_caption("intersect_triangle", renderer.leaks), renderer.image});
    figure.panels.push_back({leak_caption("half-spaces", halfspaces.leaks), halfspaces.image});
    return figure;
}

DemoFigure watertight_demo_with(std::string_view triangle_test, const DemoSize& size) {
    std::string names;
    for (const NamedTriangleTest& named : kTriangleTests) {
        if (named.name != triangle_test) {
            names += (names.empty() ? "" : ", ") + std::string(named.name);
            continue;
        }
        const PanelSize panel = panel_size(size, 1, false);
        const Scene scene = load_demo_scene("demos/watertight.test", panel);
        const LeakPanel leaks = leak_panel(scene, make_scene_camera(scene), named.test);
        DemoFigure figure;
        figure.title = "A closed mesh at 1e14 from the origin: rays through the cracks in magenta";
        figure.panels.push_back({leak_caption(std::string(named.name), leaks.leaks), leaks.image});
        return figure;
    }
    throw std::invalid_argument("no triangle test '" + std::string(triangle_test) +
                                "'; the tests are " + names);
}

}  // namespace raystep
