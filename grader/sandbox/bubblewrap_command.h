#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grader/sandbox/sandbox.h"

namespace raystep::grade {

/// The tasks bubblewrap keeps beside the program: the bwrap we start, which waits, and the PID
/// namespace's init. RLIMIT_NPROC counts them with the program's.
inline constexpr int kBubblewrapTasks = 2;

/// The command that runs `program` with `arguments` (its argv[1] on) in bubblewrap under
/// `policy`, whose paths exist and are absolute_normal: `bwrap`, its options, then the program.
/// `filter_descriptor`, when not -1, is the descriptor bubblewrap reads the program's system call
/// filter from (it installs it just before the program's exec). Throws std::runtime_error when the
/// program or the working folder would not be visible inside.
std::vector<std::string> bubblewrap_command(const std::filesystem::path& bwrap,
                                            const std::filesystem::path& program,
                                            const std::vector<std::string>& arguments,
                                            const SandboxPolicy& policy, int filter_descriptor);

}  // namespace raystep::grade
