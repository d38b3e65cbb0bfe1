#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli/scene_options.h"

namespace raystep {

/// `raystep render SCENE [-o FILE] [--threads N] [--view VIEW] [--ray-offset RULE [--epsilon E]]
/// [--spp N] [--pixel-sampling PATTERN] [--seed S] [--lookfrom X Y Z] [--trace-data FILE]`
struct RenderArguments {
    std::string scene;
    std::string output;
    std::string trace_data;  ///< where to write every pixel's record too; empty: nowhere
    int threads = 0;
    std::string view = "full";
    RayOffsetArguments ray_offset;
    SamplingArguments sampling;
    std::vector<double> lookfrom;  ///< --lookfrom: empty, or the eye in place of the scene's
};

CLI::App* add_render_command(CLI::App& app, RenderArguments& arguments);

/// Renders and writes the image; the exit code. Errors propagate to main.
int run_render(const RenderArguments& arguments);

}  // namespace raystep
