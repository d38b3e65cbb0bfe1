#pragma once

#include <filesystem>
#include <string>

namespace raystep {

/// What `raystep view` serves.
struct ViewServerOptions {
    std::string scene;  ///< the scene file it opens; empty: the page opens on the demos
    int port = 8000;    ///< on 127.0.0.1; 0 takes any free port
    int threads = 0;    ///< render threads; 0: one per hardware thread
    /// The source tree whose scenes/ the page offers; no other file is read on the page's behalf.
    std::filesystem::path project;
    /// The program's own file, watched for a rebuild; empty: rebuilds are not noticed. A
    /// `raystep-reference` beside it writes the references a release would ship
    /// (reference_files.h).
    std::filesystem::path program;
    /// Where that reference program writes them.
    std::filesystem::path reference_cache;
};

/// Exit codes of run_view_server besides 0 (stopped by Ctrl-C or SIGTERM) and 1 (a scene that
/// does not load).
constexpr int kViewPortUnavailable = 3;  ///< the port is taken, or not ours to listen on

/// Serves the page on http://127.0.0.1:PORT until Ctrl-C: the scene's views rendered as tiles
/// finish, the reference beside them, each pixel's trace, the lecture demos and their controls.
/// Prints the address once it listens. Reloads the scene when one of its files changes, and
/// restarts itself in place when its program file is rebuilt (where can_restart_program); when
/// that fails, it serves on with the build it runs and says why on the page.
int run_view_server(const ViewServerOptions& options);

}  // namespace raystep
