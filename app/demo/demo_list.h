#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "app/demo/demo_figure.h"

namespace raystep {

/// A parameter of the demo's own that `raystep view` offers as a choice, where the demo's
/// parameter is not a setting of its scene.
struct DemoParameter {
    std::string_view name;                  ///< in the page's request: "triangle"
    std::string_view label;                 ///< beside the control: "triangle test"
    std::vector<std::string_view> choices;  ///< the first is the default
};

/// A demo as `raystep demo` lists it.
struct DemoEntry {
    std::string_view name;         ///< on the command line: `raystep demo NAME`
    std::string_view description;  ///< one line: what it shows and for which stage
    DemoFigure (*make)(const DemoSize& size);
    /// The scene of scenes/ that `raystep view` opens to explore the demo live, its view, and
    /// the demo's parameter as the page's controls start it (a query string of
    /// app/view/scene_controls.h's names): shadow-acne opens its scene with epsilon to turn.
    /// Empty where the renderer cannot show the demo's idea: its cost view is the BVH's, never
    /// the grid's.
    std::string_view scene;
    std::string_view view;
    std::string_view controls;
    /// The demo's own parameter (name empty: none), and the demo as one panel at one of its
    /// choices: watertight's triangle test.
    DemoParameter parameter;
    DemoFigure (*make_with)(std::string_view choice, const DemoSize& size);
};

/// Every demo, in lecture order.
const std::vector<DemoEntry>& demo_list();

/// Every demo's name, in the order of demo_list.
std::vector<std::string> demo_names();

/// The demo with this name. Throws std::invalid_argument naming the demos when none has it.
const DemoEntry& find_demo(std::string_view name);

}  // namespace raystep
