#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "app/cli/ray_offset_option.h"

namespace raystep {

/// `raystep trace SCENE X Y [--view VIEW] [--ray-offset RULE [--epsilon E]] [--compare]
/// [--reference PATH]`
struct TraceArguments {
    std::string scene;
    int x = 0;
    int y = 0;
    std::string view = "full";
    bool compare = false;
    std::string reference;  ///< the reference build's raystep; empty means the one built here
    RayOffsetArguments ray_offset;
};

CLI::App* add_trace_command(CLI::App& app, TraceArguments& arguments);

/// Prints the trace (or, with --compare, both traces side by side). Exit code 0; 1 when a stub or
/// an error stopped the trace, or when --compare found the traces differ.
int run_trace(const TraceArguments& arguments);

}  // namespace raystep
