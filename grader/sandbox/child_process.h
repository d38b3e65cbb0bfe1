#pragma once

#include <linux/filter.h>
#include <sys/resource.h>
#include <sys/types.h>

#include <optional>
#include <string>
#include <vector>

#include "grader/sandbox/unique_fd.h"

namespace raystep::grade {

/// A kernel user and group to run as.
struct Identity {
    uid_t uid = 0;
    gid_t gid = 0;
};

/// What the child runs and under which limits: all decided before it starts, so that the child
/// only makes async-signal-safe calls (it shares the memory of the grader, whose other threads
/// may hold its locks).
struct ChildSpec {
    std::string executable;                ///< an absolute path, executed as it is
    std::vector<std::string> argv;         ///< argv[0] included
    std::vector<std::string> environment;  ///< "NAME=value": all the environment it gets
    std::string working_directory;         ///< empty: stay in ours
    rlim_t cpu_seconds = 1;                ///< RLIMIT_CPU, soft; the hard limit is one more
    rlim_t address_space_bytes = RLIM_INFINITY;
    rlim_t tasks = RLIM_INFINITY;  ///< RLIMIT_NPROC: processes and threads of the child's user
    rlim_t file_size_bytes = RLIM_INFINITY;
    rlim_t open_files = RLIM_INFINITY;  ///< RLIMIT_NOFILE
    std::optional<Identity> identity;   ///< switch to it before exec; nullopt keeps ours
    /// Give the child a fourth pipe at descriptor kAnswerDescriptor (not close-on-exec), whose
    /// other end ChildProcess::answers_read holds.
    bool answer_pipe = false;
    /// Execute the program through a descriptor the grader opened before dropping its privileges
    /// (execveat), not by its path: the program may then lie in a folder the child's user cannot
    /// enter, where no other program of that user can reach it either.
    bool exec_by_descriptor = false;
    /// The child's stdin: this descriptor (the caller keeps and closes it) instead of a pipe.
    int stdin_fd = -1;
    /// A descriptor the child gets at kInheritedDescriptor, open across the exec (the caller
    /// keeps and closes its own): bubblewrap reads its system call filter there. -1 for none.
    int inherited_fd = -1;
    /// Installed (with no_new_privs) as the last step before the exec, after the identity
    /// switch: the program runs under it from its first instruction. Empty for none.
    std::vector<sock_filter> system_call_filter;
};

/// Where a child started with an answer pipe finds it: the first descriptor after stderr, open
/// before the program's first instruction (and so before any static constructor of its).
constexpr int kAnswerDescriptor = 3;

/// Where a child finds ChildSpec::inherited_fd.
constexpr int kInheritedDescriptor = 6;

/// A started child: its pid, which is also its process group and session, and our ends of its
/// stdin, stdout and stderr: non-blocking, and close-on-exec so that no other program the grader
/// starts holds them.
struct ChildProcess {
    pid_t pid = -1;
    UniqueFd stdin_write;  ///< empty when the spec gave stdin_fd
    UniqueFd stdout_read;
    UniqueFd stderr_read;
    UniqueFd answers_read;  ///< empty unless the spec asked for an answer pipe
};

/// Starts the program; the child gets pipes for stdin, stdout and stderr (and the answer pipe, if
/// asked) and no other descriptor of ours, default signal handling, a new session, the limits and
/// the identity, then execs. Throws std::runtime_error naming the step that failed, and why, when
/// the program could not be started; the child is reaped before.
ChildProcess start_child(const ChildSpec& spec);

}  // namespace raystep::grade
