#include "sandbox_test_support.h"

#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "base/testing/catch.h"

namespace raystep::grade::testing {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

// Every process that descends from this one, live or zombie, from the parent links in /proc.
int count_descendants() {
    std::map<pid_t, pid_t> parent;
    std::error_code error;
    for (fs::directory_iterator it("/proc", error), end; !error && it != end; it.increment(error)) {
        std::ifstream file(it->path() / "stat");
        std::string stat;
        if (!std::getline(file, stat)) continue;
        // "PID (COMM) STATE PPID ...": COMM may hold spaces and parentheses, so read after the
        // last.
        const std::size_t close = stat.rfind(')');
        if (close == std::string::npos) continue;
        std::istringstream rest(stat.substr(close + 1));
        std::string state;
        pid_t ppid = 0;
        rest >> state >> ppid;
        parent[std::atoi(stat.c_str())] = ppid;
    }
    int count = 0;
    const pid_t self = getpid();
    for (const auto& [pid, ppid] : parent) {
        for (pid_t up = ppid; up > 1; up = parent.count(up) ? parent[up] : 0) {
            if (up == self) {
                ++count;
                break;
            }
        }
    }
    return count;
}

}  // namespace

std::string hostile(const std::string& name) {
    return std::string(RAYSTEP_HOSTILE_PROGRAMS) + "/hostile_" + name;
}

SandboxPolicy test_policy(bool isolate) {
    SandboxPolicy policy;
    policy.isolate = isolate;
    policy.read_only = {RAYSTEP_HOSTILE_PROGRAMS};
    policy.limits.cpu_seconds = 1;
    policy.limits.wall = std::chrono::seconds(3);
    policy.limits.address_space_bytes = std::size_t{256} << 20;
    policy.limits.processes = 16;
    policy.limits.output_bytes = std::size_t{1} << 20;
    return policy;
}

bool can_run(bool isolate) {
    if (!isolate || bubblewrap_available()) return true;
    WARN("bubblewrap cannot make a sandbox on this machine: the isolated case is skipped");
    return false;
}

bool files_protected(bool isolate) {
    if (isolate || geteuid() == 0) return true;
    WARN("without bubblewrap and root, the program runs as the tests' own user: skipped");
    return false;
}

void adopt_orphans() {
    if (prctl(PR_SET_CHILD_SUBREAPER, 1) != 0) throw std::runtime_error("cannot be a subreaper");
}

int processes_left_behind() {
    const Clock::time_point until = Clock::now() + std::chrono::seconds(1);
    int left = 0;
    do {
        while (waitpid(-1, nullptr, WNOHANG) > 0) {
        }
        left = count_descendants();
        if (left == 0) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    } while (Clock::now() < until);
    return left;
}

HostileRun run_hostile(const std::vector<std::string>& argv, const std::string& input,
                       const SandboxPolicy& policy) {
    adopt_orphans();
    HostileRun result;
    const Clock::time_point start = Clock::now();
    result.run = run_sandboxed(argv, input, policy);
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.wall_limit_seconds = std::chrono::duration<double>(policy.limits.wall).count();
    result.left_behind = processes_left_behind();
    return result;
}

TempFolder::TempFolder(unsigned mode) {
    std::string name = (fs::temp_directory_path() / "raystep-sandbox-test-XXXXXX").string();
    if (!mkdtemp(name.data())) throw std::runtime_error("cannot make a temporary folder");
    path_ = name;
    if (chmod(name.c_str(), static_cast<mode_t>(mode)) != 0) {
        throw std::runtime_error("cannot chmod " + name);
    }
}

TempFolder::~TempFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
}

std::string read_text(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

std::string start_error(const std::vector<std::string>& argv, const SandboxPolicy& policy) {
    try {
        run_sandboxed(argv, "", policy);
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

void check_contained(const HostileRun& hostile_run, bool isolate) {
    CHECK(hostile_run.run.isolated == isolate);
    CHECK(hostile_run.seconds < hostile_run.wall_limit_seconds + kReturnGraceSeconds);
    CHECK(hostile_run.left_behind == 0);
}

}  // namespace raystep::grade::testing
