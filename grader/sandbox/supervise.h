#pragma once

#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

#include "grader/sandbox/child_process.h"

namespace raystep::grade {

/// How much of stdout, stderr and the answer pipe is kept; the rest is read and dropped.
struct OutputCaps {
    std::size_t output_bytes = 0;
    std::size_t error_bytes = 0;
    std::size_t answer_bytes = 0;
};

/// When the child gets its input.
enum class InputStart {
    at_once,
    after_first_answer_line,  ///< once the answer pipe has brought a whole first line
};

/// How a supervised child ended, and what it wrote.
struct Supervision {
    /// As waitpid gives it; nullopt when it was lost (a grader that ignores SIGCHLD has its
    /// children reaped by the kernel).
    std::optional<int> wait_status;
    /// User and system time of the child and of the children it waited for (bubblewrap leaves its
    /// program's out).
    double cpu_seconds = 0.0;
    bool killed_at_wall = false;
    bool output_capped = false;   ///< stdout was longer than its cap
    bool answers_capped = false;  ///< the answer pipe was longer than its cap
    std::string output;
    std::string errors;
    std::string answers;  ///< what came on the answer pipe, if the child has one
};

/// Writes `input` to the child's stdin as fast as it reads it, from `start` on, and then closes
/// it; reads its stdout, stderr and answer pipe up to the caps and drains the rest; kills its
/// process group at `deadline`, and also once the child itself has exited; reaps it. Never throws
/// for what the child does; if it throws (out of memory), it has killed and reaped the child first.
Supervision supervise(ChildProcess& child, const std::string& input,
                      std::chrono::steady_clock::time_point deadline, OutputCaps caps,
                      InputStart start = InputStart::at_once);

}  // namespace raystep::grade
