#pragma once

#include <string>

#include "app/demo/demo_figure.h"
#include "base/scene/scene.h"
#include "renderer/view.h"

namespace raystep {

/// A scene of this repository's scenes/ folder, named relative to it
/// ("stage4/teapot-in-stadium.test"), resized to the panel with the same view from side to side:
/// a panel narrower than the scene's own image shows more above and below, a wider one less
/// (the perspective camera's fovy, or the orthographic window's bottom and top, changed to fit).
/// Throws InputError for a scene that does not load.
Scene load_demo_scene(const std::string& relative_path, const PanelSize& panel);

/// A panel of the renderer's view of a scene of scenes/ (load_demo_scene), all threads at work.
DemoPanel view_panel(const std::string& relative_path, const PanelSize& panel, View view,
                     std::string caption);

}  // namespace raystep
