// The sandbox against programs that misbehave with time, memory, processes and pipes: each ends
// as it should, reported as it happened, in bounded time, leaving nothing behind. Every case runs
// without bubblewrap and with it.
#include <chrono>
#include <csignal>
#include <string>
#include <thread>
#include <vector>

#include "base/testing/catch.h"
#include "grader/sandbox/system_call_filter.h"
#include "sandbox_test_support.h"

using namespace raystep::grade;
using namespace raystep::grade::testing;

TEST_CASE("run_sandboxed: a program that copies stdin to stdout gives all 10 MB back",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    std::string input(std::size_t{10} << 20, '\0');
    for (std::size_t k = 0; k < input.size(); ++k)
        input[k] = static_cast<char>(k * 7 % 251);
    SandboxPolicy policy = test_policy(isolate);
    policy.limits.output_bytes = std::size_t{16} << 20;

    const HostileRun echo = run_hostile({hostile("echo")}, input, policy);
    CHECK(echo.run.exit_code == 0);
    CHECK(echo.run.signal == 0);
    CHECK_FALSE(echo.run.timed_out);
    CHECK_FALSE(echo.run.output_capped);
    CHECK(echo.run.output.size() == input.size());
    const bool same = echo.run.output == input;  // not in CHECK: it would print 10 MB twice
    CHECK(same);
    CHECK(echo.run.errors.empty());
    check_contained(echo, isolate);
}

TEST_CASE("run_sandboxed: a program that reads none of 10 MB of stdin does not block the run",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    const std::string input(std::size_t{10} << 20, 'i');

    const HostileRun ignore = run_hostile({hostile("ignore_stdin")}, input, test_policy(isolate));
    CHECK(ignore.run.exit_code == 0);
    CHECK_FALSE(ignore.run.timed_out);
    CHECK(ignore.run.output == "ignored stdin\n");
    check_contained(ignore, isolate);
}

TEST_CASE("run_sandboxed: a fake 'All tests passed' and exit(0) are reported as they are",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;

    const HostileRun fake = run_hostile({hostile("fake_pass")}, "", test_policy(isolate));
    CHECK(fake.run.exit_code == 0);
    CHECK(fake.run.signal == 0);
    CHECK_FALSE(fake.run.timed_out);
    CHECK(fake.run.output ==
          std::string(79, '=') + "\nAll tests passed (42 assertions in 7 test cases)\n");
    check_contained(fake, isolate);
}

TEST_CASE("run_sandboxed: a segfault is reported as SIGSEGV, not as an exit code", "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;

    const HostileRun segfault = run_hostile({hostile("segfault")}, "", test_policy(isolate));
    CHECK(segfault.run.signal == SIGSEGV);
    CHECK(segfault.run.exit_code == -1);
    CHECK_FALSE(segfault.run.timed_out);
    check_contained(segfault, isolate);
}

TEST_CASE("run_sandboxed: an endless loop ends at the CPU limit with SIGXCPU", "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;

    // A loaded machine stretches 1 s of CPU time over more wall time: the wall limit stays far
    // away, so that only the CPU limit can end the run
    SandboxPolicy policy = test_policy(isolate);
    policy.limits.wall = std::chrono::seconds(20);

    const HostileRun spin = run_hostile({hostile("spin")}, "", policy);
    CHECK(spin.run.signal == SIGXCPU);
    CHECK(spin.run.timed_out);
    CHECK(spin.run.wall_seconds >= 0.9);
    check_contained(spin, isolate);
}

TEST_CASE("run_sandboxed: a loop that ignores SIGXCPU ends a second later with SIGKILL",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;

    SandboxPolicy policy = test_policy(isolate);
    policy.limits.wall = std::chrono::seconds(20);  // as above: only the CPU limit may end it

    const HostileRun spin = run_hostile({hostile("spin"), "--ignore-sigxcpu"}, "", policy);
    CHECK(spin.run.signal == SIGKILL);
    CHECK(spin.run.timed_out);
    CHECK(spin.run.wall_seconds >= 1.9);
    CHECK(spin.run.wall_seconds < 20.0);
    check_contained(spin, isolate);
}

TEST_CASE("run_sandboxed: a program that sleeps forever is killed at the wall-clock limit",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    SandboxPolicy policy = test_policy(isolate);
    policy.limits.wall = std::chrono::milliseconds(1000);

    const HostileRun sleep = run_hostile({hostile("sleep_forever")}, "", policy);
    CHECK(sleep.run.signal == SIGKILL);
    CHECK(sleep.run.timed_out);
    CHECK(sleep.run.wall_seconds >= 1.0);
    CHECK(sleep.run.wall_seconds < 3.0);
    check_contained(sleep, isolate);
}

TEST_CASE(
    "run_sandboxed: memory outside the address space (SysV, memfd, mqueue) ends the program at "
    "its first call with SIGSYS, named as a limit",
    "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    const std::string mode = GENERATE("sysv", "memfd", "mqueue");
    CAPTURE(isolate, mode);
    if (!can_run(isolate)) return;
    if (filter_architecture().empty()) {
        WARN("no system call filter on this architecture: nothing to test");
        return;
    }

    const HostileRun held = run_hostile({hostile("shared_memory"), mode}, "", test_policy(isolate));
    CAPTURE(held.run.output, held.run.errors);
    CHECK(held.run.signal == SIGSYS);
    CHECK(held.run.output.empty());  // not even the first 64 MiB
    CHECK_FALSE(held.run.timed_out);
    CHECK_FALSE(limit_of_signal(held.run.signal).empty());
    check_contained(held, isolate);
}

TEST_CASE("run_sandboxed: a single-process run may start threads, but a fork ends it with SIGSYS",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    if (filter_architecture().empty()) {
        WARN("no system call filter on this architecture: nothing to test");
        return;
    }
    SandboxPolicy policy = test_policy(isolate);

    // Allowed to start processes, it forks as it likes
    const HostileRun free = run_hostile({hostile("start_process")}, "", policy);
    CHECK(free.run.exit_code == 0);
    CHECK(free.run.output == "child started\nparent waited\n");
    check_contained(free, isolate);

    policy.single_process = true;
    const HostileRun forked = run_hostile({hostile("start_process")}, "", policy);
    CAPTURE(forked.run.output, forked.run.errors);
    CHECK(forked.run.signal == SIGSYS);
    CHECK(forked.run.output.empty());
    check_contained(forked, isolate);

    // The threads spend 0.9 s of CPU time: limits well above it, so that a loaded machine cannot
    // end the run by time before it shows what is under test
    policy.limits.cpu_seconds = 5;
    policy.limits.wall = std::chrono::seconds(8);
    const HostileRun threads = run_hostile({hostile("spin_threads")}, "", policy);
    CAPTURE(threads.run.errors, threads.run.timed_out);
    CHECK(threads.run.exit_code == 0);
    CHECK(threads.run.signal == 0);
    check_contained(threads, isolate);
}

TEST_CASE(
    "run_sandboxed: a single-process run reads files but making any name (file, folder, link, "
    "O_TMPFILE, socket path) ends it with SIGSYS",
    "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    const std::string mode = GENERATE("file", "folder", "link", "tmpfile", "socket");
    CAPTURE(isolate, mode);
    if (!can_run(isolate)) return;
    if (filter_architecture().empty()) {
        WARN("no system call filter on this architecture: nothing to test");
        return;
    }
    SandboxPolicy policy = test_policy(isolate);
    policy.single_process = true;

    const HostileRun named = run_hostile({hostile("make_names"), mode}, "", policy);
    CAPTURE(named.run.output, named.run.errors);
    CHECK(named.run.signal == SIGSYS);
    CHECK(named.run.output == "read: yes\n");
    check_contained(named, isolate);
}

TEST_CASE(
    "run_sandboxed: a single-process run's CPU time counts all its threads, through bubblewrap "
    "too",
    "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    SandboxPolicy policy = test_policy(isolate);
    policy.single_process = true;
    policy.limits.cpu_seconds = 5;
    policy.limits.wall = std::chrono::seconds(8);

    // Three threads of 0.3 s each: 0.9 s, less what the clocks' granularity rounds off
    const HostileRun threads = run_hostile({hostile("spin_threads")}, "", policy);
    CHECK(threads.run.exit_code == 0);
    CHECK(threads.run.cpu_seconds >= 0.85);
    CHECK(threads.run.cpu_seconds < 3.0);
    check_contained(threads, isolate);
}

TEST_CASE("run_sandboxed: unbounded allocation stops at the address-space limit", "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;

    // Touching 256 MiB of fresh pages is kernel time, which a loaded machine stretches past the
    // usual 1 s: the limit under test is the address space, so time is not allowed to end it first.
    SandboxPolicy policy = test_policy(isolate);
    policy.limits.cpu_seconds = 10;
    policy.limits.wall = std::chrono::seconds(30);
    const HostileRun allocate = run_hostile({hostile("allocate")}, "", policy);
    CAPTURE(allocate.run.exit_code, allocate.run.errors);
    CHECK(allocate.run.signal == SIGABRT);  // std::bad_alloc, uncaught
    CHECK_FALSE(allocate.run.timed_out);
    // It printed its holdings after each 16 MiB; the last is below the 256 MiB it may map.
    const std::string& output = allocate.run.output;
    REQUIRE(output.size() > 1);
    const std::size_t last_line = output.rfind('\n', output.size() - 2);
    const int held_mib =
        std::stoi(output.substr(last_line == std::string::npos ? 0 : last_line + 1));
    CAPTURE(output);
    CHECK(held_mib >= 16);
    CHECK(held_mib < 256);
    check_contained(allocate, isolate);
}

TEST_CASE("run_sandboxed: a fork bomb is held to the process limit, and its children are killed",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;

    const HostileRun bomb = run_hostile({hostile("fork_bomb")}, "", test_policy(isolate));
    CHECK(bomb.run.exit_code == 0);
    CHECK_FALSE(bomb.run.timed_out);
    // "made N: Resource temporarily unavailable". The limit is 16 tasks of the sandbox's user
    // beyond those it had at the start; allow for tasks of that user that end while it runs (ctest
    // runs this test alone, but a developer may not). Unchecked, it would make its 2,000.
    CAPTURE(bomb.run.output);
    REQUIRE(bomb.run.output.rfind("made ", 0) == 0);
    const int made = std::stoi(bomb.run.output.substr(5));
    CHECK(made < 32);
    CHECK(bomb.run.output.find("Resource temporarily unavailable") != std::string::npos);
    check_contained(bomb, isolate);
}

TEST_CASE("run_sandboxed: 1 GiB on stdout is capped, drained, and the program still exits 0",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    SandboxPolicy policy = test_policy(isolate);
    policy.limits.cpu_seconds = 8;  // a pipe moves 1 GiB in about a second; the machine is shared
    policy.limits.wall = std::chrono::seconds(9);

    const HostileRun flood = run_hostile({hostile("flood_stdout"), "1024"}, "", policy);
    CHECK(flood.run.exit_code == 0);
    CHECK(flood.run.signal == 0);
    CHECK_FALSE(flood.run.timed_out);
    CHECK(flood.run.output_capped);
    CHECK(flood.run.output.size() == policy.limits.output_bytes);
    CHECK(flood.run.output.find_first_not_of('x') == std::string::npos);
    check_contained(flood, isolate);
}

TEST_CASE("run_sandboxed: endless stderr is kept to 1 MiB until a limit ends the program",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;

    const HostileRun flood = run_hostile({hostile("flood_stderr")}, "", test_policy(isolate));
    CHECK(flood.run.timed_out);
    CHECK(flood.run.errors.size() == std::size_t{1} << 20);
    CHECK(flood.run.output.empty());
    CHECK_FALSE(flood.run.output_capped);  // the flag speaks of stdout
    check_contained(flood, isolate);
}

TEST_CASE("run_sandboxed: runs on parallel threads keep their pipes apart", "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    // As the grader compiles a submission's stages, several at a time.
    const std::size_t size = std::size_t{1} << 20;
    std::vector<std::string> outputs(4);
    std::vector<std::thread> threads;
    adopt_orphans();
    for (std::size_t k = 0; k < outputs.size(); ++k) {
        threads.emplace_back([&, k] {
            const std::string input(size, static_cast<char>('a' + k));
            try {
                outputs[k] = run_sandboxed({hostile("echo")}, input, test_policy(isolate)).output;
            } catch (const std::runtime_error& error) {
                outputs[k] = error.what();
            }
        });
    }
    for (std::thread& thread : threads)
        thread.join();
    for (std::size_t k = 0; k < outputs.size(); ++k) {
        CAPTURE(k);
        const bool own = outputs[k] == std::string(size, static_cast<char>('a' + k));
        CHECK(own);
    }
    CHECK(processes_left_behind() == 0);
}

TEST_CASE("run_sandboxed: a program that cannot be started throws and says why", "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    const SandboxPolicy policy = test_policy(isolate);

    const std::string missing = start_error({"/nonexistent/program"}, policy);
    CHECK(missing.find("/nonexistent/program: not an executable file") != std::string::npos);
    CHECK(start_error({}, policy) == "sandbox: no program to run");
    SandboxPolicy elsewhere = policy;
    elsewhere.working_directory = "/nonexistent/folder";
    CHECK(start_error({hostile("echo")}, elsewhere).find("/nonexistent/folder") !=
          std::string::npos);
}
