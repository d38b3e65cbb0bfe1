#include "app/cli/view_command.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#if RAYSTEP_HAVE_VIEW_SERVER
#include "app/demo/source_tree.h"
#include "app/view/program_restart.h"
#include "app/view/view_server.h"
#endif

namespace raystep {

CLI::App* add_view_command(CLI::App& app, ViewArguments& arguments) {
    CLI::App* command = app.add_subcommand(
        "view",
        "Watch a scene render in the browser, click a pixel for its trace beside the "
        "reference's, and show the lecture demos");
    command
        ->add_option("scene", arguments.scene,
                     "Scene file; without one the page opens on the demos")
        ->check(CLI::ExistingFile);
    command
        ->add_option("--port", arguments.port,
                     "Port on 127.0.0.1 (only this machine can connect); 0 takes any free one")
        ->check(CLI::Validator(
            [](std::string& text) {
                // Decimal digits only: CLI11 would read 0x1F44 as 8004 without a word.
                const bool digits = !text.empty() && text.size() <= 5 &&
                                    std::all_of(text.begin(), text.end(), [](unsigned char c) {
                                        return std::isdigit(c) != 0;
                                    });
                if (digits && std::stoi(text) <= 65535) return std::string();
                return "a port is a number from 0 to 65535, not '" + text + "'";
            },
            "PORT"));
    command->add_option("--threads", arguments.threads, "Render threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    return command;
}

int run_view(const ViewArguments& arguments, const char* argv0) {
#if RAYSTEP_HAVE_VIEW_SERVER
    ViewServerOptions options;
    options.scene = arguments.scene;
    options.port = arguments.port;
    options.threads = arguments.threads;
    options.project = source_tree();
    options.program = own_program_file(argv0);
    // Beside the build's bin/ folder, in the build tree, which nothing commits.
    options.reference_cache = options.program.parent_path().parent_path() / "view-references";
    return run_view_server(options);
#else
    (void)arguments;
    (void)argv0;
    std::fprintf(stderr,
                 "raystep: this build has no `view`: it needs cpp-httplib, which CMake did not "
                 "find. Install it (Debian or Ubuntu: libcpp-httplib-dev; macOS: brew install "
                 "cpp-httplib; vcpkg: cpp-httplib), then configure and build again.\n");
    return 1;
#endif
}

}  // namespace raystep
