#include "grader/sandbox/bubblewrap_command.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <system_error>

#include "grader/sandbox/sandbox_paths.h"
#include "grader/sandbox/sandbox_user.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

// What a dynamically linked C++ program and g++ need of the system, read-only: programs,
// libraries, the dynamic linker's cache, and the alternatives that /usr/bin/c++ and cc point
// through. Nothing else of /etc, which holds the host's configuration and secrets. Where /bin or
// /lib is a symlink (merged /usr), bubblewrap binds the folder it points to: its --symlink would
// write the link's target into its tmpfs as file data, which RLIMIT_FSIZE limits (a probe allowed
// no file at all could not start).
constexpr const char* kSystemPaths[] = {"/usr",
                                        "/bin",
                                        "/sbin",
                                        "/lib",
                                        "/lib32",
                                        "/lib64",
                                        "/libx32",
                                        "/etc/alternatives",
                                        "/etc/ld.so.cache"};

// tmpfs takes size 0 for "no limit"; a /tmp for a program that may write no file is one page.
constexpr std::size_t kSmallestTmp = 4096;

bool present(const fs::path& path) {
    std::error_code error;
    return fs::exists(path, error);
}

struct Bind {
    fs::path path;
    bool writable = false;
};

// The policy's folders, each under the folders that contain it: bubblewrap mounts in order, and a
// folder bound before its parent would be hidden by it.
std::vector<Bind> policy_binds(const SandboxPolicy& policy) {
    std::vector<Bind> binds;
    for (const fs::path& path : policy.read_only)
        binds.push_back({path, false});
    if (!policy.writable.empty()) binds.push_back({policy.writable, true});
    const auto depth = [](const Bind& bind) {
        return std::distance(bind.path.begin(), bind.path.end());
    };
    std::stable_sort(binds.begin(), binds.end(),
                     [&](const Bind& a, const Bind& b) { return depth(a) < depth(b); });
    return binds;
}

}  // namespace

std::vector<std::string> bubblewrap_command(const fs::path& bwrap, const fs::path& program,
                                            const std::vector<std::string>& arguments,
                                            const SandboxPolicy& policy, int filter_descriptor) {
    const std::string uid = std::to_string(kSandboxUid);
    const std::string gid = std::to_string(kSandboxGid);
    std::vector<std::string> command = {
        bwrap.string(),
        // New user, PID, IPC, UTS, network and cgroup namespaces: no network (a loopback that is
        // down), no view of the host's processes. --unshare-user in so many words: --unshare-all
        // only tries it, and goes on without one where that fails.
        "--unshare-all", "--unshare-user",
        // No user namespace inside: the kernel's widest door for an unprivileged process.
        "--disable-userns", "--uid", uid, "--gid", gid,
        // The namespace's init gets SIGKILL when the bwrap we start dies, and with it every
        // process in the namespace. That bwrap dies when we kill it at the wall-clock limit, and
        // also exits as soon as the program does, while the init would go on waiting for what the
        // program left running: this is what ends those.
        "--die-with-parent",
        // A session of its own: it cannot push input into a terminal (TIOCSTI, CVE-2017-5226).
        "--new-session"};
    // A program that may start no process needs no init to reap what it starts: it is the PID
    // namespace's first process itself, bubblewrap's own child, so that bubblewrap reaps it and
    // its CPU time reaches our wait (through an init, bubblewrap exits without reaping it, and
    // the time is lost). The run still ends with it: the namespace dies with its first process.
    if (policy.single_process) command.push_back("--as-pid-1");
    // The system call filter, installed by bubblewrap just before it executes the program, so
    // that its own set-up (clone with new namespaces) is not under it.
    if (filter_descriptor >= 0) {
        command.insert(command.end(), {"--seccomp", std::to_string(filter_descriptor)});
    }

    // The system, read-only (bubblewrap binds nosuid), then a private /proc, /dev and /tmp.
    std::vector<fs::path> visible;
    for (const char* path : kSystemPaths) {
        if (!present(path)) continue;
        command.insert(command.end(), {"--ro-bind", path, path});
        visible.emplace_back(path);
    }
    // /tmp is memory, which RLIMIT_AS does not count: no larger than the largest file it may
    // write.
    const std::size_t tmp_bytes = std::max(policy.limits.file_size_bytes, kSmallestTmp);
    command.insert(command.end(), {"--proc", "/proc", "--dev", "/dev", "--size",
                                   std::to_string(tmp_bytes), "--tmpfs", "/tmp"});

    // The policy's folders, at the same place as on the host.
    for (const Bind& bind : policy_binds(policy)) {
        command.insert(command.end(), {bind.writable ? "--bind" : "--ro-bind", bind.path.string(),
                                       bind.path.string()});
        visible.push_back(bind.path);
    }

    // The root and /dev are tmpfs that bubblewrap made, writable by the program and of no set
    // size: read-only, or it could fill the host's memory through them. (The binds and /tmp are
    // mounts of their own and keep their access.)
    command.insert(command.end(), {"--remount-ro", "/dev", "--remount-ro", "/"});

    // The program and its working folder must be inside, or bubblewrap would fail as if the
    // program had.
    const auto shown = [&](const fs::path& path) {
        return std::any_of(visible.begin(), visible.end(),
                           [&](const fs::path& folder) { return is_within(path, folder); });
    };
    if (!shown(program)) {
        throw std::runtime_error("sandbox: cannot start " + program.string() +
                                 ": it is not inside any folder the sandbox shows");
    }
    const fs::path& directory = policy.working_directory;
    if (directory != "/" && directory != "/tmp" && !(shown(directory) && present(directory))) {
        throw std::runtime_error("sandbox: cannot start " + program.string() +
                                 ": its working folder " + directory.string() +
                                 " is not a folder the sandbox shows");
    }
    command.insert(command.end(), {"--chdir", directory.string(), "--", program.string()});
    command.insert(command.end(), arguments.begin(), arguments.end());
    return command;
}

}  // namespace raystep::grade
