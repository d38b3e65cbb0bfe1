#include "app/demo/demo_scene.h"

#include <cmath>
#include <filesystem>

#include <glm/trigonometric.hpp>

#include "app/demo/source_tree.h"
#include "base/scene/scene_loader.h"
#include "renderer/tile_renderer.h"

namespace raystep {

Scene load_demo_scene(const std::string& relative_path, const PanelSize& panel) {
    Scene scene = load_scene(source_tree() / "scenes" / relative_path);
    // Keep the width of the view: scale its height by the change of aspect ratio
    const double taller = (static_cast<double>(scene.width) / scene.height) /
                          (static_cast<double>(panel.width) / panel.height);
    CameraSpec& camera = scene.camera;
    if (camera.ortho) {
        const double middle = 0.5 * (camera.ortho->bottom + camera.ortho->top);
        const double half = 0.5 * (camera.ortho->top - camera.ortho->bottom) * taller;
        camera.ortho->bottom = middle - half;
        camera.ortho->top = middle + half;
    } else {
        const double half_angle =
            std::atan(std::tan(glm::radians(camera.fovy_degrees) / 2) * taller);
        camera.fovy_degrees = glm::degrees(2.0 * half_angle);
    }
    scene.width = panel.width;
    scene.height = panel.height;
    return scene;
}

DemoPanel view_panel(const std::string& relative_path, const PanelSize& panel, View view,
                     std::string caption) {
    const Scene scene = load_demo_scene(relative_path, panel);
    RenderOptions options;
    options.view = view;
    return {std::move(caption), render_image(prepare_render_scene(scene), options)};
}

}  // namespace raystep
