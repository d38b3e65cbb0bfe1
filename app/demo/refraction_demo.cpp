// raystep demo refraction: a glass cube at four indices, and where total internal reflection sets
// in.

#include <cmath>
#include <cstdio>

#include <glm/trigonometric.hpp>

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"
#include "renderer/tile_renderer.h"

namespace raystep {

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
