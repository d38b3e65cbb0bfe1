// The sandbox against programs that reach for what is not theirs: files outside the writable
// folder, secrets, the network, the grader's descriptors and environment, a session of their own.
// Without bubblewrap only the user (nobody, when the grader is root) and the process group stand
// in the way; the cases that need bubblewrap say so.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>

#include "base/testing/catch.h"
#include "grader/sandbox/sandbox_user.h"
#include "sandbox_test_support.h"

using namespace raystep::grade;
using namespace raystep::grade::testing;

namespace fs = std::filesystem;

namespace {

// A TCP socket listening on 127.0.0.1 at a port the kernel picks; closed at the end.
class LocalListener {
  public:
    LocalListener() : fd_(socket(AF_INET, SOCK_STREAM, 0)) {
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t size = sizeof address;
        REQUIRE(fd_ >= 0);
        REQUIRE(bind(fd_, reinterpret_cast<sockaddr*>(&address), size) == 0);
        REQUIRE(listen(fd_, 4) == 0);
        REQUIRE(getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &size) == 0);
        port_ = ntohs(address.sin_port);
    }
    ~LocalListener() { close(fd_); }
    LocalListener(const LocalListener&) = delete;
    LocalListener& operator=(const LocalListener&) = delete;

    std::string port() const { return std::to_string(port_); }

  private:
    int fd_;
    int port_ = 0;
};

}  // namespace

TEST_CASE("run_sandboxed: a file written outside the writable folder never reaches the host",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    const TempFolder writable(0755);
    const TempFolder elsewhere(0755);
    SandboxPolicy policy = test_policy(isolate);
    policy.writable = writable.path();

    const fs::path inside = writable.path() / "inside.txt";
    const HostileRun allowed =
        run_hostile({hostile("write_file"), inside.string(), "mine"}, "", policy);
    CHECK(allowed.run.exit_code == 0);
    CHECK(read_text(inside) == "mine");
    check_contained(allowed, isolate);

    if (!files_protected(isolate)) return;
    const fs::path outside = elsewhere.path() / "outside.txt";
    const HostileRun denied =
        run_hostile({hostile("write_file"), outside.string(), "stolen"}, "", policy);
    CAPTURE(denied.run.output);
    CHECK(denied.run.exit_code == 1);
    CHECK_FALSE(fs::exists(outside));
    check_contained(denied, isolate);
}

TEST_CASE("run_sandboxed: g++ compiles and links in the sandbox, and what it made runs there",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    const TempFolder sources(0755);
    const TempFolder objects(0755);
    const fs::path source = sources.path() / "hello.cpp";
    std::ofstream(source) << "#include <cstdio>\nint main() { std::puts(\"hello, sandbox\"); }\n";
    fs::permissions(source, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);

    // Only the sources read-only, the objects writable, and what the sandbox shows of the system.
    SandboxPolicy compile = test_policy(isolate);
    compile.read_only = {sources.path()};
    compile.writable = objects.path();
    compile.working_directory = objects.path();
    compile.limits.cpu_seconds = 20;
    compile.limits.wall = std::chrono::seconds(30);
    compile.limits.address_space_bytes = std::size_t{1} << 30;
    const fs::path program = objects.path() / "hello";
    const HostileRun gxx =
        run_hostile({"c++", "-O1", source.string(), "-o", program.string()}, "", compile);
    CAPTURE(gxx.run.errors);
    REQUIRE(gxx.run.exit_code == 0);
    check_contained(gxx, isolate);

    SandboxPolicy run = test_policy(isolate);
    run.read_only = {objects.path()};
    const HostileRun hello = run_hostile({program.string()}, "", run);
    CHECK(hello.run.exit_code == 0);
    CHECK(hello.run.output == "hello, sandbox\n");
    check_contained(hello, isolate);
}

TEST_CASE("run_sandboxed: a program allowed no file still starts, and dies of SIGXFSZ writing one",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    const TempFolder writable(0755);
    SandboxPolicy policy = test_policy(isolate);
    policy.writable = writable.path();
    policy.limits.file_size_bytes = 0;  // as the grader runs its probes

    const fs::path file = writable.path() / "answers.txt";
    const HostileRun write =
        run_hostile({hostile("write_file"), file.string(), "too much"}, "", policy);
    CHECK(write.run.signal == SIGXFSZ);
    CHECK_FALSE(write.run.timed_out);
    CHECK(read_text(file).empty());
    check_contained(write, isolate);
}

TEST_CASE("run_sandboxed: with bubblewrap, /tmp is private and the system is read-only",
          "[sandbox]") {
    if (!can_run(true)) return;
    const fs::path host_tmp =
        fs::temp_directory_path() / ("raystep-sandbox-test-" + std::to_string(getpid()) + ".txt");
    const HostileRun tmp =
        run_hostile({hostile("write_file"), host_tmp.string(), "private"}, "", test_policy(true));
    CHECK(tmp.run.exit_code == 0);  // it wrote, to its own /tmp
    CHECK_FALSE(fs::exists(host_tmp));
    check_contained(tmp, true);

    for (const char* path : {"/usr/raystep-sandbox-test.txt", "/raystep-sandbox-test.txt",
                             "/dev/shm/raystep-sandbox-test.txt"}) {
        CAPTURE(path);
        const HostileRun system =
            run_hostile({hostile("write_file"), path, "x"}, "", test_policy(true));
        CHECK(system.run.output.find("Read-only file system") != std::string::npos);
        CHECK_FALSE(fs::exists(path));
        check_contained(system, true);
    }
}

TEST_CASE("run_sandboxed: a secret outside the read-only paths cannot be read", "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    if (!files_protected(isolate)) return;
    const TempFolder secrets(0700);
    const fs::path secret = secrets.path() / "answers.txt";
    std::ofstream(secret) << "the hidden expected answers";
    fs::permissions(secret, fs::perms::owner_read | fs::perms::owner_write);

    const HostileRun read =
        run_hostile({hostile("read_file"), secret.string()}, "", test_policy(isolate));
    CAPTURE(read.run.output);
    CHECK(read.run.exit_code == 1);
    CHECK(read.run.output.find("hidden") == std::string::npos);
    check_contained(read, isolate);
}

TEST_CASE("run_sandboxed: with bubblewrap, only the read-only paths of the host are visible",
          "[sandbox]") {
    if (!can_run(true)) return;
    const TempFolder shared(0755);
    const fs::path file = shared.path() / "public.txt";
    std::ofstream(file) << "anyone may read this on the host";
    fs::permissions(file, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);

    // Readable by anyone on the host, but not among the policy's paths: not there at all.
    const HostileRun unseen =
        run_hostile({hostile("read_file"), file.string()}, "", test_policy(true));
    CHECK(unseen.run.exit_code == 1);
    CHECK(unseen.run.output.find("No such file or directory") != std::string::npos);
    check_contained(unseen, true);

    SandboxPolicy policy = test_policy(true);
    policy.read_only.push_back(shared.path());
    const HostileRun seen = run_hostile({hostile("read_file"), file.string()}, "", policy);
    CHECK(seen.run.exit_code == 0);
    CHECK(seen.run.output == "anyone may read this on the host");
    check_contained(seen, true);
}

TEST_CASE("run_sandboxed: without bubblewrap a program reaches 127.0.0.1 (so the check can fail)",
          "[sandbox]") {
    const LocalListener listener;
    const HostileRun reach =
        run_hostile({hostile("connect"), "127.0.0.1", listener.port()}, "", test_policy(false));
    CHECK(reach.run.output == "connected\n");
    check_contained(reach, false);
}

TEST_CASE("run_sandboxed: with bubblewrap, there is no network, not even 127.0.0.1", "[sandbox]") {
    if (!can_run(true)) return;
    const LocalListener listener;
    const HostileRun local =
        run_hostile({hostile("connect"), "127.0.0.1", listener.port()}, "", test_policy(true));
    CAPTURE(local.run.output);
    CHECK(local.run.exit_code == 1);
    CHECK(local.run.output.find("cannot connect") == 0);
    check_contained(local, true);

    const HostileRun remote =
        run_hostile({hostile("connect"), "1.1.1.1", "53"}, "", test_policy(true));
    CAPTURE(remote.run.output);
    CHECK(remote.run.exit_code == 1);
    CHECK(remote.run.output.find("Network is unreachable") != std::string::npos);
    check_contained(remote, true);
}

TEST_CASE("run_sandboxed: with bubblewrap, a process that left the session dies with the run",
          "[sandbox]") {
    if (!can_run(true)) return;
    const HostileRun escape = run_hostile({hostile("escape_session")}, "", test_policy(true));
    CHECK(escape.run.exit_code == 0);
    CHECK_FALSE(escape.run.timed_out);
    check_contained(escape, true);
}

TEST_CASE("run_sandboxed: without bubblewrap, a root grader's run ends what left its session",
          "[sandbox]") {
    if (geteuid() != 0) return;  // the run keeps the grader's user, which it cannot kill wholesale
    const HostileRun escape = run_hostile({hostile("escape_session")}, "", test_policy(false));
    CHECK(escape.run.exit_code == 0);
    CHECK_FALSE(escape.run.timed_out);
    check_contained(escape, false);
}

TEST_CASE("run_sandboxed: the program is never root, and gets only PATH, PWD and stdio of ours",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    const SandboxPolicy policy = test_policy(isolate);

    const HostileRun id = run_hostile({"id", "-u"}, "", policy);
    // Inside bubblewrap, nobody; outside it, a root grader's run has a user of its own.
    if (isolate) CHECK(id.run.output == "65534\n");
    if (!isolate && geteuid() == 0) {
        const unsigned long uid = std::stoul(id.run.output);
        CHECK(uid >= kRunUsersFirst);
        CHECK(uid < kRunUsersFirst + kRunUsersCount);
    }
    check_contained(id, isolate);

    const HostileRun env = run_hostile({"env"}, "", policy);
    CHECK(env.run.output == "PATH=/usr/local/bin:/usr/bin:/bin\nPWD=/\n");
    check_contained(env, isolate);

    // A descriptor of the grader's that is not close-on-exec stays out too: ls sees its own
    // three and the one it lists with.
    std::FILE* held = std::fopen("/dev/null", "r");
    REQUIRE(held);
    const HostileRun fds = run_hostile({"ls", "/proc/self/fd"}, "", policy);
    std::fclose(held);
    CHECK(fds.run.output == "0\n1\n2\n3\n");
    check_contained(fds, isolate);
}

TEST_CASE("run_sandboxed: with bubblewrap, a program outside what the sandbox shows throws",
          "[sandbox]") {
    if (!can_run(true)) return;
    const TempFolder hidden(0755);
    const fs::path copy = hidden.path() / "echo";
    fs::copy_file(hostile("echo"), copy);
    const std::string unseen = start_error({copy.string()}, test_policy(true));
    CHECK(unseen.find("not inside any folder the sandbox shows") != std::string::npos);
    SandboxPolicy missing = test_policy(true);
    missing.read_only.push_back(hidden.path() / "nothing");
    CHECK(start_error({hostile("echo")}, missing).find("does not exist") != std::string::npos);
}
