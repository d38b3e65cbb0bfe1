#include "grader/sandbox/sandbox_user.h"

#include <grp.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

bool all_digits(const std::string& name) {
    return !name.empty() && name.find_first_not_of("0123456789") == std::string::npos;
}

// The number after `field` ("Uid:", "Threads:") in a /proc/PID/status file; the first of them.
std::optional<unsigned long> status_field(const std::string& status, const std::string& field) {
    const std::size_t at = status.find("\n" + field);
    if (at == std::string::npos) return std::nullopt;
    std::istringstream value(status.substr(at + 1 + field.size()));
    unsigned long number = 0;
    if (!(value >> number)) return std::nullopt;
    return number;
}

}  // namespace

std::optional<Identity> program_identity() {
    if (geteuid() != 0) return std::nullopt;
    // Drawn at random, so that two graders on one machine rarely meet; one that some process
    // already has is passed over.
    static std::mutex mutex;
    static std::mt19937 draw{std::random_device{}()};
    for (;;) {
        uid_t uid = 0;
        {
            const std::lock_guard<std::mutex> lock(mutex);
            uid = kRunUsersFirst + static_cast<uid_t>(draw() % kRunUsersCount);
        }
        if (tasks_of(uid) == 0) return Identity{uid, static_cast<gid_t>(uid)};
    }
}

void end_processes_of(const Identity& identity) {
    const pid_t child = fork();
    if (child == 0) {
        const bool as_user =
            setgroups(0, nullptr) == 0 && setgid(identity.gid) == 0 && setuid(identity.uid) == 0;
        // kill(-1) reaches every process the caller may signal, but never the caller itself.
        _exit(as_user && (kill(-1, SIGKILL) == 0 || errno == ESRCH) ? 0 : 1);
    }
    if (child < 0) throw std::runtime_error("sandbox: cannot end a run's processes: fork failed");
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
}

rlim_t tasks_of(uid_t uid) {
    rlim_t tasks = 0;
    std::error_code error;
    for (fs::directory_iterator it("/proc", error), end; !error && it != end; it.increment(error)) {
        if (!all_digits(it->path().filename().string())) continue;
        // A process may end while we read: its file is then empty or gone, and it counts 0.
        std::ifstream file(it->path() / "status");
        std::stringstream text;
        text << file.rdbuf();
        const std::string status = "\n" + text.str();
        const std::optional<unsigned long> real_uid = status_field(status, "Uid:");
        const std::optional<unsigned long> threads = status_field(status, "Threads:");
        if (real_uid == uid && threads) tasks += *threads;
    }
    return tasks;
}

void hand_over(const fs::path& folder, const Identity& identity) {
    if (lchown(folder.c_str(), identity.uid, identity.gid) != 0) {
        throw std::runtime_error("sandbox: cannot give the writable folder " + folder.string() +
                                 " to uid " + std::to_string(identity.uid) + ": " +
                                 std::strerror(errno));
    }
}

std::vector<fs::path> open_to_sandbox_user(const std::vector<fs::path>& paths) {
    std::vector<fs::path> open;
    const std::optional<Identity> identity = program_identity();
    if (!identity) return open;
    for (const fs::path& path : paths) {
        // A child asks, as that user, and answers with its exit code: 0 when it could reach it.
        const pid_t child = fork();
        if (child == 0) {
            const bool as_user = setgroups(0, nullptr) == 0 && setgid(identity->gid) == 0 &&
                                 setuid(identity->uid) == 0;
            _exit(as_user && (access(path.c_str(), R_OK) == 0 || access(path.c_str(), X_OK) == 0)
                      ? 0
                      : 1);
        }
        int status = 0;
        if (child < 0 || waitpid(child, &status, 0) != child) {
            throw std::runtime_error("sandbox: cannot ask what the sandbox's user may read: " +
                                     std::string(std::strerror(errno)));
        }
        if (WIFEXITED(status) && WEXITSTATUS(status) == 0) open.push_back(path);
    }
    return open;
}

void reclaim(const fs::path& path) {
    if (geteuid() != 0) return;
    if (lchown(path.c_str(), geteuid(), getegid()) != 0) {
        throw std::runtime_error("sandbox: cannot take back " + path.string() + ": " +
                                 std::strerror(errno));
    }
}

}  // namespace raystep::grade
