#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace raystep {

/// `raystep info SCENE`: what the scene uses and which stages render it.
struct InfoArguments {
    std::string scene;
};

CLI::App* add_info_command(CLI::App& app, InfoArguments& arguments);

int run_info(const InfoArguments& arguments);

}  // namespace raystep
