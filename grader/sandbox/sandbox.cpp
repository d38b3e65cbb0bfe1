#include "grader/sandbox/sandbox.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "grader/sandbox/bubblewrap_command.h"
#include "grader/sandbox/child_process.h"
#include "grader/sandbox/sandbox_paths.h"
#include "grader/sandbox/sandbox_user.h"
#include "grader/sandbox/supervise.h"
#include "grader/sandbox/system_call_filter.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

// stderr is kept up to this: enough for a compiler's first errors, and it bounds our memory.
constexpr std::size_t kErrorBytes = std::size_t{1} << 20;

// The policy with every path absolute_normal, as bubblewrap takes them and is_within compares.
SandboxPolicy normalized(const SandboxPolicy& policy) {
    SandboxPolicy normal = policy;
    for (fs::path& path : normal.read_only)
        path = absolute_normal(path);
    if (!normal.writable.empty()) normal.writable = absolute_normal(normal.writable);
    normal.working_directory = absolute_normal(normal.working_directory);
    return normal;
}

// The policy's paths must exist, with bubblewrap or without: bubblewrap would fail on a missing
// one as if the program had, and a mistake of the grader's should show wherever it runs.
void require_paths(const SandboxPolicy& policy) {
    std::error_code error;
    for (const fs::path& path : policy.read_only) {
        if (!fs::exists(path, error)) {
            throw std::runtime_error("sandbox: the read-only path " + path.string() +
                                     " does not exist");
        }
    }
    if (!policy.writable.empty() && !fs::is_directory(policy.writable, error)) {
        throw std::runtime_error("sandbox: the writable folder " + policy.writable.string() +
                                 " is not a folder");
    }
}

// The limits and identity every run has, with or without bubblewrap.
ChildSpec limited_spec(const SandboxLimits& limits, bool isolated) {
    ChildSpec spec;
    spec.environment = {std::string("PATH=") + kSandboxPath};
    // RLIMIT_CPU counts whole seconds: a fraction rounds up, and no limit is below one second.
    spec.cpu_seconds = static_cast<rlim_t>(std::max(1.0, std::ceil(limits.cpu_seconds)));
    spec.address_space_bytes = limits.address_space_bytes;
    spec.file_size_bytes = limits.file_size_bytes;
    spec.open_files = static_cast<rlim_t>(std::max(0, limits.open_files));
    spec.identity = program_identity();
    // A fork bomb is held by RLIMIT_NPROC, which the kernel enforces on every uid but 0: hence a
    // program that is never root (sandbox_user.h), bubblewrap's included (inside its user
    // namespace it has uid 65534, and outside it is the run's own user or the grader's, never the
    // root that a root grader would map in). The limit counts every task of that real uid, so
    // what the user already runs (the grader's own processes when it is not root) is added, or
    // the program could not start one process; a run's own user has none (program_identity drew a
    // uid that no process has). Inside bubblewrap the kernel also counts per user namespace, so
    // there the limit holds for the sandbox alone.
    // Whatever a run leaves is then killed with it (supervise.h, end_processes_of).
    const rlim_t already = spec.identity ? 0 : tasks_of(getuid());
    spec.tasks = already + static_cast<rlim_t>(std::max(0, limits.processes)) +
                 (isolated ? kBubblewrapTasks : 0);
    return spec;
}

// How the program ended, from the status of the process we started.
void read_status(const Supervision& supervision, bool isolated, SandboxRun& run) {
    if (!supervision.wait_status) return;
    const int status = *supervision.wait_status;
    if (WIFSIGNALED(status)) {
        run.signal = WTERMSIG(status);
    } else if (WIFEXITED(status)) {
        const int code = WEXITSTATUS(status);
        // bubblewrap hands the program's end on as a shell does: its exit code, or 128 plus the
        // signal that killed it.
        if (isolated && code > 128 && code - 128 < NSIG) {
            run.signal = code - 128;
        } else {
            run.exit_code = code;
        }
    }
}

// Whether the CPU limit ended the program. SIGXCPU comes at the soft limit; SIGKILL a second
// later, at the hard one, for a program that caught or ignored SIGXCPU. A SIGKILL can have other
// senders (the OOM killer, the program itself), so it counts when the CPU time reached the limit.
// Through bubblewrap's init the program's CPU time is lost (SandboxRun::cpu_seconds), so there the
// wall-clock time stands in for it: a single thread cannot reach the hard limit sooner.
bool at_cpu_limit(const SandboxRun& run, bool cpu_time_complete, double soft_seconds) {
    if (run.signal == SIGXCPU) return true;
    if (run.signal != SIGKILL) return false;
    return cpu_time_complete ? run.cpu_seconds >= soft_seconds
                             : run.wall_seconds >= soft_seconds + 1.0;
}

// The filter's instructions in a pipe, for bubblewrap to read at kInheritedDescriptor: a few
// hundred bytes, which the pipe holds before anyone reads them.
UniqueFd filter_pipe(const std::vector<sock_filter>& filter) {
    int ends[2];
    if (pipe2(ends, O_CLOEXEC) != 0) {
        throw std::runtime_error(std::string("sandbox: cannot make a pipe: ") +
                                 std::strerror(errno));
    }
    UniqueFd read_end(ends[0]);
    UniqueFd write_end(ends[1]);
    const std::size_t bytes = filter.size() * sizeof(sock_filter);
    if (write(write_end.get(), filter.data(), bytes) != static_cast<ssize_t>(bytes)) {
        throw std::runtime_error(std::string("sandbox: cannot write the system call filter: ") +
                                 std::strerror(errno));
    }
    return read_end;
}

}  // namespace

SandboxRun run_sandboxed(const std::vector<std::string>& argv, const std::string& input,
                         const SandboxPolicy& policy) {
    if (argv.empty()) throw std::runtime_error("sandbox: no program to run");
    const fs::path program = find_executable(argv.front());
    const SandboxPolicy normal = normalized(policy);
    require_paths(normal);
    const bool isolated = policy.isolate && bubblewrap_available();

    // What to execute: bubblewrap with the program inside, or the program itself. Its argv[0] is
    // its absolute path, which means the same inside and out.
    ChildSpec spec = limited_spec(policy.limits, isolated);
    const std::vector<std::string> arguments(argv.begin() + 1, argv.end());
    const std::vector<sock_filter> filter = system_call_filter(policy.single_process);
    UniqueFd filter_for_bubblewrap;
    if (isolated) {
        if (!filter.empty()) {
            filter_for_bubblewrap = filter_pipe(filter);
            spec.inherited_fd = filter_for_bubblewrap.get();
        }
        spec.argv = bubblewrap_command(find_executable("bwrap"), program, arguments, normal,
                                       filter.empty() ? -1 : kInheritedDescriptor);
    } else {
        spec.system_call_filter = filter;
        spec.argv = {program.string()};
        spec.argv.insert(spec.argv.end(), arguments.begin(), arguments.end());
        spec.working_directory = normal.working_directory.string();
        spec.environment.push_back("PWD=" + spec.working_directory);  // as bubblewrap sets it
        // By descriptor: the grader's private folders (a submission's probes) stay shut to the
        // sandbox's user, who could otherwise run any probe it can name.
        spec.exec_by_descriptor = true;
    }
    spec.executable = spec.argv.front();
    spec.answer_pipe = policy.answer_channel;
    UniqueFd stdin_file;
    if (!policy.stdin_file.empty()) {
        stdin_file.reset(open(policy.stdin_file.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY));
        if (!stdin_file) {
            throw std::runtime_error("sandbox: cannot open " + policy.stdin_file.string() + ": " +
                                     std::strerror(errno));
        }
        spec.stdin_fd = stdin_file.get();
    }
    if (spec.identity && !normal.writable.empty()) hand_over(normal.writable, *spec.identity);

    const Clock::time_point start = Clock::now();
    ChildProcess child = start_child(spec);
    Supervision supervision =
        supervise(child, input, start + policy.limits.wall,
                  {policy.limits.output_bytes, kErrorBytes, policy.limits.answer_bytes},
                  policy.answer_channel && policy.input_after_first_answer
                      ? InputStart::after_first_answer_line
                      : InputStart::at_once);

    // Outside bubblewrap, what the program left running (a process that started a session of its
    // own escapes the kill of the group) ends with the run: it is the run's user's alone.
    if (!isolated && spec.identity) end_processes_of(*spec.identity);

    SandboxRun run;
    run.isolated = isolated;
    run.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    run.cpu_seconds = supervision.cpu_seconds;
    read_status(supervision, isolated, run);
    const bool cpu_time_complete = !isolated || policy.single_process;
    run.timed_out = supervision.killed_at_wall ||
                    at_cpu_limit(run, cpu_time_complete, static_cast<double>(spec.cpu_seconds));
    run.output_capped = supervision.output_capped;
    run.answers_capped = supervision.answers_capped;
    run.output = std::move(supervision.output);
    run.answers = std::move(supervision.answers);
    run.errors = std::move(supervision.errors);
    return run;
}

bool bubblewrap_available() {
    // Asked once: the answer holds while the grader runs, and asking starts a sandbox. The
    // question is the command every isolated run uses, with `true` for the program, so that a
    // kernel without unprivileged user namespaces, or a bubblewrap too old for an option we
    // pass, says no here instead of failing every run as if the program had.
    static const bool available = [] {
        SandboxPolicy policy;
        policy.isolate = false;
        policy.limits.cpu_seconds = 5;
        policy.limits.wall = std::chrono::seconds(10);
        SandboxPolicy probe_like = policy;
        probe_like.single_process = true;
        try {
            const std::vector<std::string> command = bubblewrap_command(
                find_executable("bwrap"), find_executable("true"), {}, normalized(probe_like), -1);
            return run_sandboxed(command, "", policy).exit_code == 0;
        } catch (const std::runtime_error&) {
            return false;
        }
    }();
    return available;
}

std::string limit_of_signal(int signal) {
    switch (signal) {
        case SIGSYS:
            return "it made a system call the sandbox forbids: asking for memory outside its "
                   "address space (shared memory, message queues, memfd), which the memory limit "
                   "could not count, or in a probe starting a process or making a file, folder or "
                   "link";
        case SIGXFSZ:
            return "it wrote a file past the sandbox's file size limit (a probe may write none)";
        case SIGXCPU:
            return "it reached the sandbox's CPU time limit";
        default:
            return "";
    }
}

}  // namespace raystep::grade
