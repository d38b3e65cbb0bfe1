#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace raystep {

/// `raystep view [SCENE] [--port N] [--threads N]`: the renderer in the browser (app/view/).
struct ViewArguments {
    std::string scene;
    int port = 8000;
    int threads = 0;
};

CLI::App* add_view_command(CLI::App& app, ViewArguments& arguments);

/// Serves the page until Ctrl-C (app/view/view_server.h): 0 when stopped, 1 for a scene that does
/// not load, 3 when the port is taken. `argv0` finds the program's own file, which it watches
/// for a rebuild.
int run_view(const ViewArguments& arguments, const char* argv0);

}  // namespace raystep
