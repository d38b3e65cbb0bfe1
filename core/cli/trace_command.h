#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace raystep {

/// `raystep trace SCENE X Y [--view VIEW] [--compare] [--reference PATH]`
struct TraceArguments {
    std::string scene;
    int x = 0;
    int y = 0;
    std::string view = "full";
    bool compare = false;
    std::string reference;  ///< the reference build's raystep; empty means the one built here
};

CLI::App* add_trace_command(CLI::App& app, TraceArguments& arguments);

/// Prints the trace (or, with --compare, both traces side by side); the exit code. A stub that
/// stops the trace ends it with its message and exit code 1.
int run_trace(const TraceArguments& arguments);

}  // namespace raystep
