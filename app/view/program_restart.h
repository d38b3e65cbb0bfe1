#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace raystep {

// A rebuild reloads the renderer: the stages are static libraries linked into the program, so
// the new code runs only in a new process. `raystep view` watches its own file and, once a build
// has replaced it, starts it again in its own place with the same port, so that the page
// reconnects and renders with the student's fix.

/// The program's own file, found at start-up, before a build can replace it: /proc/self/exe on
/// Linux, else `argv0` as given or on the PATH. Empty when it cannot be found; then a rebuild is
/// not noticed.
std::filesystem::path own_program_file(const char* argv0);

/// True where restart_program can replace this process (POSIX systems).
bool can_restart_program();

/// True when `program` is a file this process may run: a link that failed has deleted it, and
/// one still writing it has not yet made it executable.
bool program_can_run(const std::filesystem::path& program);

/// Replaces this process with `program` run with `arguments` (arguments[0] is the program's
/// name); returns only when that fails, with the reason.
std::string restart_program(const std::filesystem::path& program,
                            const std::vector<std::string>& arguments);

}  // namespace raystep
