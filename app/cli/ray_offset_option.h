#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "base/scene/scene.h"

namespace raystep {

/// `--ray-offset RULE [--epsilon E]`: overrides the scene's `rayoffset` (docs/stage6.md).
struct RayOffsetArguments {
    std::string rule;  ///< empty: the scene's own
    double epsilon = 0.0;

    /// The options as given, for a second raystep that must do the same (trace --compare).
    std::string command_line() const;
};

/// The options on a command; parsing fails (a command-line error) when the epsilon is missing for
/// along-ray or along-normal, or given to error-bound or without a rule.
void add_ray_offset_options(CLI::App& command, RayOffsetArguments& arguments);

/// The scene with the rule the command line gives, if any.
void apply_ray_offset(const RayOffsetArguments& arguments, Scene& scene);

}  // namespace raystep
