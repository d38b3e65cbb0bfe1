#include "grader/sandbox/child_process.h"

#include <fcntl.h>
#include <linux/seccomp.h>
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

namespace raystep::grade {

namespace {

// The child's steps between its start and its exec, in order; a failing one is reported to the
// parent.
enum class Step : int {
    signals,
    stdio,
    descriptors,
    session,
    limits,
    identity,
    directory,
    filter,
    exec
};

const char* step_name(Step step) {
    switch (step) {
        case Step::signals:
            return "resetting its signal handling";
        case Step::stdio:
            return "connecting stdin, stdout and stderr";
        case Step::descriptors:
            return "closing the grader's descriptors";
        case Step::session:
            return "starting a session";
        case Step::limits:
            return "setting its resource limits";
        case Step::identity:
            return "switching to the sandbox's user";
        case Step::directory:
            return "entering its working folder";
        case Step::filter:
            return "installing its system call filter";
        case Step::exec:
            return "executing it";
    }
    return "starting it";
}

struct ChildFailure {
    Step step;
    int error;
};

struct Pipe {
    UniqueFd read;
    UniqueFd write;
};

[[noreturn]] void throw_errno(const std::string& what) {
    throw std::runtime_error("sandbox: " + what + ": " + std::strerror(errno));
}

// A pipe whose ends are close-on-exec and numbered 3 or more, so that the child's dup2 onto 0, 1
// and 2 never overwrites one of them before it is used (a grader started with stdin closed gets
// descriptor 0 from pipe()).
Pipe make_pipe() {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw_errno("cannot make a pipe");
    Pipe pipe{UniqueFd(fds[0]), UniqueFd(fds[1])};
    for (UniqueFd* end : {&pipe.read, &pipe.write}) {
        if (end->get() >= 3) continue;
        const int moved = fcntl(end->get(), F_DUPFD_CLOEXEC, 3);
        if (moved < 0) throw_errno("cannot move a pipe");
        end->reset(moved);
    }
    return pipe;
}

void make_non_blocking(const UniqueFd& fd) {
    const int flags = fcntl(fd.get(), F_GETFL);
    if (flags < 0 || fcntl(fd.get(), F_SETFL, flags | O_NONBLOCK) < 0) {
        throw_errno("cannot make a pipe non-blocking");
    }
}

// NULL-terminated pointers into `strings`, for execve.
std::vector<char*> c_strings(std::vector<std::string>& strings) {
    std::vector<char*> pointers;
    for (std::string& s : strings)
        pointers.push_back(s.data());
    pointers.push_back(nullptr);
    return pointers;
}

// The functions the child runs, uninstrumented by AddressSanitizer: it would call its no-return
// hook before each [[noreturn]] call, which reads the bounds of the stack of the grader's thread,
// whose memory the child shares, while the child runs on a stack of its own (start_child).
#if defined(__SANITIZE_ADDRESS__)
#define RAYSTEP_CHILD_SIDE __attribute__((no_sanitize_address))
#else
#define RAYSTEP_CHILD_SIDE
#endif

// In the child: tell the parent which step failed, and stop. Only async-signal-safe calls.
[[noreturn]] RAYSTEP_CHILD_SIDE void report_failure(int report_fd, Step step) {
    const ChildFailure failure{step, errno};
    // A write that fails means the parent is gone, and there is no one left to tell.
    [[maybe_unused]] const ssize_t told = write(report_fd, &failure, sizeof failure);
    _exit(127);
}

// Lowers a limit of the child; never above the hard limit it already has (only root may raise
// one, and the grader's own limits are a ceiling for what it starts).
bool lower_limit(int resource, rlim_t soft, rlim_t hard) {
    struct rlimit now {};
    if (getrlimit(resource, &now) != 0) return false;
    const struct rlimit wanted { std::min(soft, now.rlim_max), std::min(hard, now.rlim_max) };
    return setrlimit(resource, &wanted) == 0;
}

struct ChildEnds {
    int stdin_read;
    int stdout_write;
    int stderr_write;
    int report_write;
    int answer_write;          ///< -1 for none
    int program;               ///< the program, opened by the parent, or -1 to execute it by path
    int inherited;             ///< ChildSpec::inherited_fd, or -1
    const sock_fprog* filter;  ///< nullptr for none
};

// The descriptors the child places, each at a fixed number: the answer pipe (kept across the
// exec), the report pipe and the program (both closed by the exec), the inherited descriptor
// (kept). Every number from kFirstFreeDescriptor up is closed before the exec.
constexpr int kReportDescriptor = kAnswerDescriptor + 1;
constexpr int kProgramDescriptor = kAnswerDescriptor + 2;
static_assert(kInheritedDescriptor == kAnswerDescriptor + 3);
constexpr int kFirstFreeDescriptor = kAnswerDescriptor + 4;

// The child, from its start to exec. Only async-signal-safe calls that write nothing of the
// grader's memory, which it shares (start_child), but the errno of the thread that started it:
// another thread of the grader may hold a lock (malloc's, say), and the grader's objects must be
// as they were when the child is gone.
[[noreturn]] RAYSTEP_CHILD_SIDE void become_program(const ChildSpec& spec, char* const* argv,
                                                    char* const* envp, const ChildEnds& ends,
                                                    long open_max) {
    // Default signal handling: a handler of the grader must not run in the child before the exec,
    // and an ignored signal stays ignored across it (a grader ignoring SIGPIPE would hand that
    // on). The parent blocked every signal across the start; unblock them at the exec.
    for (int sig = 1; sig < NSIG; ++sig) {
        struct sigaction action {};
        if (sigaction(sig, nullptr, &action) != 0 || action.sa_handler == SIG_DFL) continue;
        action = {};
        action.sa_handler = SIG_DFL;
        sigemptyset(&action.sa_mask);
        if (sigaction(sig, &action, nullptr) != 0) report_failure(ends.report_write, Step::signals);
    }
    // Its stdin, stdout and stderr are our pipes.
    if (dup2(ends.stdin_read, 0) < 0 || dup2(ends.stdout_write, 1) < 0 ||
        dup2(ends.stderr_write, 2) < 0) {
        report_failure(ends.report_write, Step::stdio);
    }
    // No other descriptor of the grader's: some may not be close-on-exec (a report being written,
    // say), and the program could read or write them, or hold a pipe of another run open. Each
    // descriptor the child keeps is first copied above the fixed numbers, so that placing one
    // never overwrites another not yet placed, then put at its number; the rest are closed.
    const int report_high = fcntl(ends.report_write, F_DUPFD_CLOEXEC, kFirstFreeDescriptor);
    if (report_high < 0) report_failure(ends.report_write, Step::descriptors);
    const auto high = [&](int fd) {
        if (fd < 0) return -1;
        const int copy = fcntl(fd, F_DUPFD_CLOEXEC, kFirstFreeDescriptor);
        if (copy < 0) report_failure(report_high, Step::descriptors);
        return copy;
    };
    const int program_high = high(ends.program);
    const int answer_high = high(ends.answer_write);
    const int inherited_high = high(ends.inherited);
    if (dup3(report_high, kReportDescriptor, O_CLOEXEC) < 0) {
        report_failure(report_high, Step::descriptors);
    }
    const int report_fd = kReportDescriptor;
    if ((program_high >= 0 && dup3(program_high, kProgramDescriptor, O_CLOEXEC) < 0) ||
        (answer_high >= 0 && dup2(answer_high, kAnswerDescriptor) < 0) ||
        (inherited_high >= 0 && dup2(inherited_high, kInheritedDescriptor) < 0)) {
        report_failure(report_fd, Step::descriptors);
    }
    if (answer_high < 0) close(kAnswerDescriptor);
    if (program_high < 0) close(kProgramDescriptor);
    if (inherited_high < 0) close(kInheritedDescriptor);
    if (close_range(static_cast<unsigned>(kFirstFreeDescriptor), ~0U, 0) !=
        0) {  // Linux 5.9; older: one by one
        for (long fd = kFirstFreeDescriptor; fd < open_max; ++fd)
            close(static_cast<int>(fd));
    }
    // A new session, and so a new process group whose id is our pid: the parent can kill the
    // whole group at once, and no terminal of the grader's can signal it or be read by it.
    if (setsid() < 0) report_failure(report_fd, Step::session);

    // The limits. The soft CPU limit sends SIGXCPU, which a program may catch or ignore; the hard
    // one, a second later, sends SIGKILL, which it cannot. No core files: they are big, slow to
    // write and of no use to a grade.
    if (!lower_limit(RLIMIT_CPU, spec.cpu_seconds, spec.cpu_seconds + 1) ||
        !lower_limit(RLIMIT_AS, spec.address_space_bytes, spec.address_space_bytes) ||
        !lower_limit(RLIMIT_NPROC, spec.tasks, spec.tasks) ||
        !lower_limit(RLIMIT_FSIZE, spec.file_size_bytes, spec.file_size_bytes) ||
        !lower_limit(RLIMIT_NOFILE, spec.open_files, spec.open_files) ||
        !lower_limit(RLIMIT_CORE, 0, 0)) {
        report_failure(report_fd, Step::limits);
    }

    // The identity, groups first (setgid and setgroups need the privilege setuid gives up). By
    // the kernel's calls, not libc's: in a threaded program libc's setuid changes every thread's
    // identity, signalling the threads it knows of, which here are the grader's (see start_child).
    // Then not dumpable: the switch makes the memory the child shares with the grader as dumpable
    // as fs.suid_dumpable says, and a process of the sandbox's user must never trace the child
    // and through it write the grader's memory before the exec gives the child its own.
    if (spec.identity) {
        if (syscall(SYS_setgroups, 0, nullptr) != 0 ||
            syscall(SYS_setgid, spec.identity->gid) != 0 ||
            syscall(SYS_setuid, spec.identity->uid) != 0 || getuid() != spec.identity->uid ||
            geteuid() != spec.identity->uid || getgid() != spec.identity->gid ||
            getegid() != spec.identity->gid || prctl(PR_SET_DUMPABLE, 0, 0, 0, 0) != 0) {
            report_failure(report_fd, Step::identity);
        }
    }

    if (!spec.working_directory.empty() && chdir(spec.working_directory.c_str()) != 0) {
        report_failure(report_fd, Step::directory);
    }

    // The filter last: the steps above make calls it may refuse. no_new_privs is the price the
    // kernel asks of a process without privilege for installing one, and the program keeps it.
    if (ends.filter != nullptr && (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0 ||
                                   prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, ends.filter) != 0)) {
        report_failure(report_fd, Step::filter);
    }
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    if (program_high >= 0) {
        syscall(SYS_execveat, kProgramDescriptor, "", argv, envp, AT_EMPTY_PATH);
    } else {
        execve(spec.executable.c_str(), argv, envp);
    }
    report_failure(report_fd, Step::exec);
}

// What become_program is given, passed through clone's one pointer.
struct ChildStart {
    const ChildSpec* spec;
    char* const* argv;
    char* const* envp;
    const ChildEnds* ends;
    long open_max;
};

RAYSTEP_CHILD_SIDE int start_program(void* start) {
    const auto* s = static_cast<const ChildStart*>(start);
    become_program(*s->spec, s->argv, s->envp, *s->ends, s->open_max);
}

// The child's own stack while it shares the grader's memory: become_program's frames need a few
// kilobytes. Left uninitialised: only the pages the child touches are ever faulted in.
constexpr std::size_t kChildStackBytes = 256 << 10;

void reap(pid_t pid) {
    while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
    }
}

}  // namespace

ChildProcess start_child(const ChildSpec& spec) {
    // Everything the child needs, made before it starts.
    std::vector<std::string> argv_strings = spec.argv;
    std::vector<std::string> env_strings = spec.environment;
    const std::vector<char*> argv = c_strings(argv_strings);
    const std::vector<char*> envp = c_strings(env_strings);
    Pipe in = make_pipe();
    Pipe out = make_pipe();
    Pipe err = make_pipe();
    Pipe report = make_pipe();
    Pipe answers;
    if (spec.answer_pipe) {
        answers = make_pipe();
        make_non_blocking(answers.read);
    }
    for (const UniqueFd* ours : {&in.write, &out.read, &err.read})
        make_non_blocking(*ours);
    UniqueFd program;
    if (spec.exec_by_descriptor) {
        program.reset(open(spec.executable.c_str(), O_PATH | O_CLOEXEC));
        if (!program) throw_errno("cannot open " + spec.executable);
    }
    const long open_max = sysconf(_SC_OPEN_MAX);
    const int stdin_read = spec.stdin_fd >= 0 ? spec.stdin_fd : in.read.get();
    const sock_fprog filter{static_cast<unsigned short>(spec.system_call_filter.size()),
                            const_cast<sock_filter*>(spec.system_call_filter.data())};
    const ChildEnds ends{stdin_read,          out.write.get(),
                         err.write.get(),     report.write.get(),
                         answers.write.get(), program.get(),
                         spec.inherited_fd,   spec.system_call_filter.empty() ? nullptr : &filter};

    // The child shares the grader's memory until its exec, and this thread waits for it
    // (CLONE_VM | CLONE_VFORK, as posix_spawn starts a program). A fork would copy the grader's
    // page tables, and every page the grader wrote afterwards would fault to be copied: on a
    // virtual machine that shadows page tables, that was over a tenth of a grade's processor time
    // (docs/measurements/grading-time.md). Only the memory is shared: the child's descriptors,
    // signal handlers, limits and identity are its own. Every signal is blocked across the
    // start, so that none reaches a handler of the grader's in the child before it has reset
    // them all.
    const std::unique_ptr<char[]> stack(new char[kChildStackBytes]);
    ChildStart start{&spec, argv.data(), envp.data(), &ends, open_max};
    sigset_t all;
    sigset_t previous;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &previous);
    const pid_t pid = clone(start_program, stack.get() + kChildStackBytes,
                            CLONE_VM | CLONE_VFORK | SIGCHLD, &start);
    const int clone_error = errno;
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    if (pid < 0) {
        throw std::runtime_error("sandbox: cannot start " + spec.executable +
                                 ": clone: " + std::strerror(clone_error));
    }

    // The child's ends are the child's. The report pipe closes at its exec; a failure arrives
    // before that.
    in.read.reset();
    out.write.reset();
    err.write.reset();
    report.write.reset();
    answers.write.reset();
    ChildFailure failure{};
    ssize_t got = 0;
    do {
        got = read(report.read.get(), &failure, sizeof failure);
    } while (got < 0 && errno == EINTR);
    if (got > 0) {
        reap(pid);
        std::string what =
            "sandbox: cannot start " + spec.executable + ": " + step_name(failure.step);
        if (failure.step == Step::directory) what += " " + spec.working_directory;
        throw std::runtime_error(what + ": " + std::strerror(failure.error));
    }

    ChildProcess child;
    child.pid = pid;
    if (spec.stdin_fd < 0) child.stdin_write = std::move(in.write);
    child.stdout_read = std::move(out.read);
    child.stderr_read = std::move(err.read);
    child.answers_read = std::move(answers.read);
    return child;
}

}  // namespace raystep::grade
