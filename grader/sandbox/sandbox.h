#pragma once

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace raystep::grade {

// Running untrusted programs (a submission's probe, or the compiler on a submission's files) so
// that nothing they do reaches beyond their run: ARCHITECTURE.md, "The grader".
//
// Always (Linux; the grader runs there): rlimits on CPU time, address space, processes and file
// size, a wall-clock timeout after which the whole process group is killed, and a cap on the
// output read (the rest is drained and thrown away, so a flood neither fills memory nor blocks).
// Where bubblewrap (`bwrap`) is installed and works: a new user, PID, IPC, UTS and network
// namespace (no network), a new session, an unprivileged uid, a private /tmp, and a filesystem
// made only of read-only binds of the paths the policy names plus one writable folder.
//
// The program never runs as root: when the grader is root, it runs as a user of its run's own
// (sandbox_user.h: a fresh uid and gid, outside bubblewrap; nobody, 65534, inside it), with or
// without bubblewrap. So the paths in read_only must be readable by others, with every folder
// above them searchable, and the writable folder is given to the run's user (chown, the folder
// only) before the run. Without bubblewrap the program is executed through a descriptor the
// grader opened, so it may lie in a folder that only the grader can enter. Its environment is
// PATH (/usr/local/bin:/usr/bin:/bin) and PWD, nothing of the grader's. A run ends when the
// program's first process exits; whatever it left running is killed then: by bubblewrap's PID
// namespace, or without it by killing every process of the run's user.
//
// Memory: rlimits bound each process, not the run, and RLIMIT_AS counts only what is mapped. So
// every run also gets a system call filter (system_call_filter.h) that kills a program asking
// for memory outside its address space (SysV shared memory, message queues and semaphores, POSIX
// message queues, memfd files, io_uring), and a cap on its open descriptors, which bounds what it
// can hold in pipe and socket buffers. A single_process run (a probe) may start no process
// besides its threads: one address space, one descriptor table, and the kernel's account of its
// CPU time is the whole run's. Files it writes are bounded by RLIMIT_FSIZE each, and with
// bubblewrap /tmp is a tmpfs of that size; the number of files written in the writable folder is
// not bounded. docs/instructor.md, "What student code can touch", has the whole argument. When
// the grader is not root, runs without bubblewrap share the grader's user: nothing then keeps
// one from another, or from the grader's files.

struct SandboxLimits {
    double cpu_seconds = 10.0;
    std::chrono::milliseconds wall{20000};
    std::size_t address_space_bytes = std::size_t{2} << 30;
    /// RLIMIT_NPROC: processes and threads, beyond those its user already runs.
    int processes = 64;
    /// RLIMIT_FSIZE: the largest file it may write; with bubblewrap, also the size of its /tmp.
    std::size_t file_size_bytes = 64u << 20;
    std::size_t output_bytes = 64u << 20;  ///< stdout read at most; stderr at most 1 MiB
    /// RLIMIT_NOFILE: with the process limit, what bounds the pipe and socket buffers it holds.
    int open_files = 64;
    std::size_t answer_bytes = 64u << 20;  ///< the answer channel read at most, when there is one
};

struct SandboxPolicy {
    SandboxLimits limits;
    /// Paths visible inside, read-only, at the same place (the system's /usr, /lib... are added
    /// by the sandbox itself).
    std::vector<std::filesystem::path> read_only;
    /// The one folder the program may write, visible at the same place; empty for none.
    std::filesystem::path writable;
    /// The working folder inside.
    std::filesystem::path working_directory = "/";
    /// Use bubblewrap when it is installed and works; false runs with rlimits and timeout only.
    bool isolate = true;
    /// Give the program an answer channel: a pipe at descriptor kAnswerDescriptor (3), open
    /// before its first instruction, whose contents come back as SandboxRun::answers. A probe
    /// answers there, so that nothing the submission prints on stdout, even before main, can
    /// reach or break the protocol.
    bool answer_channel = false;
    /// With an answer channel: the program's stdin gets `input` only once it has written a first
    /// line there. A probe writes it from main, so that no query waits on stdin while the
    /// submission's static constructors run.
    bool input_after_first_answer = false;
    /// The program's stdin is this file, which the grader opens itself: the program needs no way
    /// to it, and is never shown the folder it lies in. A folder is opened as a folder, for a
    /// program that reads it through the descriptor (raystep-unpack). Empty: stdin is the run's
    /// `input`.
    std::filesystem::path stdin_file;
    /// The program may start threads but no process (system_call_filter.h): a probe. Its CPU time
    /// is then the whole run's, with bubblewrap too, where it runs as the PID namespace's first
    /// process (bubblewrap's --as-pid-1), so that bubblewrap reaps it and passes its time on.
    bool single_process = false;
};

struct SandboxRun {
    int exit_code = -1;  ///< the program's, when it exited
    /// The signal that killed it, or 0. With bubblewrap, which passes on 128 + the signal as its
    /// exit code, an exit code of 129 to 192 is read as that signal.
    int signal = 0;
    /// Killed at the wall-clock limit, or by SIGXCPU/SIGKILL at the CPU limit (with bubblewrap,
    /// which hides the program's CPU time, a SIGKILL counts once the wall time reached the limit).
    bool timed_out = false;
    bool output_capped = false;   ///< it wrote more than output_bytes
    bool answers_capped = false;  ///< it wrote more than answer_bytes on the answer channel
    std::string output;           ///< stdout, up to the cap
    std::string errors;           ///< stderr, up to 1 MiB
    std::string answers;          ///< the answer channel, up to its cap (answer_channel only)
    double wall_seconds = 0.0;
    /// User and system CPU time, as the kernel accounted it when the program ended: all of a
    /// single_process run's; otherwise the first process's and what it waited for (and nothing of
    /// the program's through bubblewrap).
    double cpu_seconds = 0.0;
    bool isolated = false;  ///< bubblewrap was used
};

/// What a signal that ended a sandboxed program says about the sandbox's limits, in words ("it
/// made a system call the sandbox forbids: ..."), or empty for a signal of the program's own
/// doing (SIGSEGV, SIGABRT...).
std::string limit_of_signal(int signal);

/// Runs argv[0] with arguments, `input` (or policy.stdin_file) on its stdin, under the policy.
/// argv[0] without a slash is looked up in the sandbox's PATH; the program gets its absolute path
/// as argv[0]. Never throws for what the program does; throws std::runtime_error only when the
/// program cannot be started at all (not found, a path of the policy missing, the program or
/// working folder outside what bubblewrap would show), and says why.
SandboxRun run_sandboxed(const std::vector<std::string>& argv, const std::string& input,
                         const SandboxPolicy& policy);

/// True when bubblewrap is installed and can make a sandbox here (it needs user namespaces):
/// asked once, by running `true` in the sandbox every isolated run gets.
bool bubblewrap_available();

}  // namespace raystep::grade
