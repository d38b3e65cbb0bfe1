#include "grader/sandbox/supervise.h"

#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <vector>

namespace raystep::grade {

namespace {

using Clock = std::chrono::steady_clock;

// How long poll waits when no pipe has news: how late we notice the wall-clock limit, or that the
// child exited while something else still holds its pipes open (an exit is no event on them).
constexpr int kPollSliceMs = 10;

// Once the child has exited and its group is killed, how long we keep draining its pipes: the
// killed die within milliseconds, but a process that left the group (setsid) may hold them open
// for as long as it likes, and the run must end.
constexpr std::chrono::milliseconds kDrainGrace{1000};

// Bytes moved per read or write: a pipe's default capacity on Linux.
constexpr std::size_t kChunk = 64 * 1024;

// Writing to a pipe whose reader has gone raises SIGPIPE, whose default action would end the
// grader, not the program. Block it in this thread while we write, take back any that a failed
// write left pending, and give the thread its mask back at the end.
class SigpipeBlocked {
  public:
    SigpipeBlocked() {
        sigemptyset(&sigpipe_);
        sigaddset(&sigpipe_, SIGPIPE);
        pthread_sigmask(SIG_BLOCK, &sigpipe_, &previous_);
        sigset_t pending;
        sigpending(&pending);
        pending_before_ = sigismember(&pending, SIGPIPE) == 1;
    }
    ~SigpipeBlocked() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
    SigpipeBlocked(const SigpipeBlocked&) = delete;
    SigpipeBlocked& operator=(const SigpipeBlocked&) = delete;

    /// After a write failed with EPIPE: removes the SIGPIPE it raised, unless one was pending
    /// before we blocked it (then it is the same signal, and not ours to take).
    void discard_raised() {
        if (pending_before_) return;
        const timespec no_wait{0, 0};
        sigtimedwait(&sigpipe_, nullptr, &no_wait);
    }

  private:
    sigset_t sigpipe_{};
    sigset_t previous_{};
    bool pending_before_ = false;
};

// True once the child has exited. WNOWAIT leaves it a zombie: its pid, and so its process group's
// id, stays taken until we reap it, so that killing the group cannot hit a stranger that reused
// the number. An error (ECHILD: a grader that ignores SIGCHLD has its children reaped for it)
// counts as exited, or we would wait for the deadline.
bool has_exited(pid_t pid) {
    siginfo_t info{};
    if (waitid(P_PID, pid, &info, WEXITED | WNOHANG | WNOWAIT) != 0) return errno != EINTR;
    return info.si_pid == pid;
}

// Reads what one pipe has. Keeps it up to `cap` bytes and drops the rest: a flood must neither
// fill our memory nor, were we to stop reading, block the program on a full pipe; and closing
// the pipe instead would end it with SIGPIPE, an outcome of our making. Closes the pipe at its
// end.
void read_some(UniqueFd& pipe, std::vector<char>& buffer, std::string& kept, std::size_t cap,
               bool& capped) {
    const ssize_t got = read(pipe.get(), buffer.data(), buffer.size());
    if (got < 0 && (errno == EAGAIN || errno == EINTR)) return;
    if (got <= 0) {
        pipe.reset();
        return;
    }
    const std::size_t room = cap - std::min(cap, kept.size());
    const std::size_t take = std::min(room, static_cast<std::size_t>(got));
    kept.append(buffer.data(), take);
    if (take < static_cast<std::size_t>(got)) capped = true;
}

double seconds(const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec;
}

}  // namespace

Supervision supervise(ChildProcess& child, const std::string& input, Clock::time_point deadline,
                      OutputCaps caps, InputStart start) {
    Supervision result;
    SigpipeBlocked sigpipe;
    std::vector<char> buffer(kChunk);
    bool error_capped = false;  // stderr has no flag of its own: its cap only bounds our memory
    std::size_t written = 0;
    bool exited = false;
    Clock::time_point drain_until{};
    if (input.empty()) child.stdin_write.reset();

    try {
        for (;;) {
            // The run ends with its first process, as bubblewrap's ends with its PID namespace:
            // whatever it left running in its group is killed, then the pipes are drained.
            const Clock::time_point now = Clock::now();
            if (!exited && has_exited(child.pid)) {
                kill(-child.pid, SIGKILL);
                exited = true;
                child.stdin_write.reset();
                drain_until = now + kDrainGrace;
            } else if (!exited && !result.killed_at_wall && now >= deadline) {
                kill(-child.pid, SIGKILL);
                result.killed_at_wall = true;
            }
            const bool pipes_closed =
                !child.stdout_read && !child.stderr_read && !child.answers_read;
            if (exited && (pipes_closed || now >= drain_until)) break;

            // Wait for any pipe to be ready, at most one slice. stdin waits, when asked to, for
            // the answer pipe's first line.
            const bool input_open =
                start == InputStart::at_once || result.answers.find('\n') != std::string::npos;
            pollfd fds[4] = {{input_open ? child.stdin_write.get() : -1, POLLOUT, 0},
                             {child.stdout_read.get(), POLLIN, 0},
                             {child.stderr_read.get(), POLLIN, 0},
                             {child.answers_read.get(), POLLIN, 0}};  // poll skips fd -1
            if (poll(fds, 4, kPollSliceMs) < 0) continue;             // EINTR

            // Feed stdin as far as the pipe takes it; close it at the end of the input, or when
            // the program closed its end (EPIPE).
            if (fds[0].revents & (POLLERR | POLLHUP)) {
                child.stdin_write.reset();
            } else if (fds[0].revents & POLLOUT) {
                const std::size_t size = std::min(kChunk, input.size() - written);
                const ssize_t put = write(child.stdin_write.get(), input.data() + written, size);
                const int error = put < 0 ? errno : 0;
                if (put > 0) written += static_cast<std::size_t>(put);
                if (error == EPIPE) sigpipe.discard_raised();
                if ((put < 0 && error != EAGAIN && error != EINTR) || written == input.size()) {
                    child.stdin_write.reset();
                }
            }
            if (fds[1].revents) {
                read_some(child.stdout_read, buffer, result.output, caps.output_bytes,
                          result.output_capped);
            }
            if (fds[2].revents) {
                read_some(child.stderr_read, buffer, result.errors, caps.error_bytes, error_capped);
            }
            if (fds[3].revents) {
                read_some(child.answers_read, buffer, result.answers, caps.answer_bytes,
                          result.answers_capped);
            }
        }
    } catch (...) {
        kill(-child.pid, SIGKILL);
        while (waitpid(child.pid, nullptr, 0) < 0 && errno == EINTR) {
        }
        throw;
    }

    // Reap it. Its rusage counts the CPU time of the descendants it waited for too, but not
    // through bubblewrap, which leaves its program's out.
    rusage usage{};
    int status = 0;
    pid_t reaped = 0;
    do {
        reaped = wait4(child.pid, &status, 0, &usage);
    } while (reaped < 0 && errno == EINTR);
    if (reaped == child.pid) result.wait_status = status;
    result.cpu_seconds = seconds(usage.ru_utime) + seconds(usage.ru_stime);
    return result;
}

}  // namespace raystep::grade
