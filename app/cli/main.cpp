#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli/check_command.h"
#include "app/cli/command_registry.h"
#include "app/cli/compare_command.h"
#include "app/cli/demo_command.h"
#include "app/cli/info_command.h"
#include "app/cli/render_command.h"
#include "app/cli/trace_command.h"
#include "app/cli/view_command.h"
#include "base/errors/input_error.h"
#include "base/errors/not_implemented.h"

// The `raystep` command. Library code throws; only here do errors become a message on stderr and
// an exit code: 0 success, 1 a failure (bad input, a stub, an error), 2 a bad command line, and
// for `view` 3 when it cannot listen on its port (app/view/view_server.h).
// `compare` answers with 1 for a render that fails, so that anything which stops it comparing
// exits 2 instead, as diff(1) does.
int main(int argc, char** argv) {
    using namespace raystep;

    CLI::App app{"raystep: a ray tracer built one lecture at a time", "raystep"};
    app.require_subcommand(1);
    RenderArguments render;
    InfoArguments info;
    TraceArguments trace;
    CheckArguments check;
    DemoArguments demo;
    CompareArguments compare;
    ViewArguments view;
    CLI::App* render_command = add_render_command(app, render);
    CLI::App* info_command = add_info_command(app, info);
    CLI::App* trace_command = add_trace_command(app, trace);
    CLI::App* check_command = add_check_command(app, check);
    CLI::App* compare_command = add_compare_command(app, compare);
    CLI::App* view_command = add_view_command(app, view);
    std::vector<AddedCommand> added;
    for (const AddCommand add : CommandRegistry::entries())
        added.push_back(add(app));
    CLI::App* demo_command = add_demo_command(app, demo);

    if (argc == 1) {
        std::fputs(app.help().c_str(), stderr);
        return 2;
    }
    // A word that names no command gets the list of those this build has: CLI11 alone would say
    // only that a subcommand is required (a student release has no `bench`, for one).
    if (argv[1][0] != '-') {
        std::string names;
        bool known = false;
        for (const CLI::App* command : app.get_subcommands({})) {
            known = known || command->get_name() == argv[1];
            names += (names.empty() ? "" : ", ") + command->get_name();
        }
        if (!known) {
            std::fprintf(stderr, "raystep: no command '%s' in this build; its commands are: %s\n",
                         argv[1], names.c_str());
            return 2;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? 0 : 2;
    }

    try {
        if (render_command->parsed()) return run_render(render);
        if (info_command->parsed()) return run_info(info);
        if (trace_command->parsed()) return run_trace(trace);
        if (check_command->parsed()) return run_check(check);
        if (compare_command->parsed()) return run_compare(compare);
        if (demo_command->parsed()) return run_demo(demo);
        if (view_command->parsed()) return run_view(view, argv[0]);
        for (const AddedCommand& command : added) {
            if (command.command->parsed()) return command.run();
        }
    } catch (const NotImplemented& stub) {
        std::fprintf(stderr, "raystep: %s\n", stub.what());
    } catch (const InputError& error) {
        std::fprintf(stderr, "%s\n", error.what());
    } catch (const std::exception& error) {
        std::fprintf(stderr, "raystep: %s\n", error.what());
    }
    return compare_command->parsed() ? 2 : 1;
}
