#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace raystep {

/// `raystep demo [NAME] [-o FILE] [--size WxH] [--list]`
struct DemoArguments {
    std::string name;    ///< empty: list the demos
    std::string output;  ///< empty: demo-NAME.png in the current folder
    std::string size;    ///< WIDTHxHEIGHT, checked by parse_demo_size; empty: 640 x 480
    bool list = false;
};

CLI::App* add_demo_command(CLI::App& app, DemoArguments& arguments);

/// Lists the demos, or renders one and writes its image; the exit code. Errors propagate to main.
int run_demo(const DemoArguments& arguments);

}  // namespace raystep
