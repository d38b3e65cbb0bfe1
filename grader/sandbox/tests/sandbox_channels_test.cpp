// The sandbox's channels besides stdout and stderr: the answer channel a probe answers on, a file
// given as stdin, and a program executed through a descriptor where no bubblewrap hides folders.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "base/testing/catch.h"
#include "sandbox_test_support.h"

using namespace raystep::grade;
using namespace raystep::grade::testing;

namespace fs = std::filesystem;

TEST_CASE("run_sandboxed: the answer channel is descriptor 3, kept apart from stdout",
          "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    SandboxPolicy policy = test_policy(isolate);
    policy.answer_channel = true;
    const HostileRun run = run_hostile({hostile("answer_channel")}, "", policy);
    CHECK(run.run.exit_code == 0);
    CHECK(run.run.output == "printed on stdout\n");
    CHECK(run.run.answers == "written on descriptor 3\n");
    CHECK(run.left_behind == 0);
}

TEST_CASE(
    "run_sandboxed: input held until the answer channel's first line reaches no one before it",
    "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    SandboxPolicy policy = test_policy(isolate);
    policy.answer_channel = true;

    const HostileRun at_once = run_hostile({hostile("ready_then_echo")}, "query\n", policy);
    CHECK(at_once.run.output == "waiting before ready: yes\nquery\n");

    policy.input_after_first_answer = true;
    const HostileRun held = run_hostile({hostile("ready_then_echo")}, "query\n", policy);
    CHECK(held.run.output == "waiting before ready: no\nquery\n");
    CHECK(held.run.answers == "ready\n");
    CHECK(held.left_behind == 0);
}

TEST_CASE("run_sandboxed: without an answer channel, descriptor 3 is not open", "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    const HostileRun run = run_hostile({hostile("answer_channel")}, "", test_policy(isolate));
    CHECK(run.run.output == "printed on stdout\nno descriptor 3\n");
    CHECK(run.run.answers.empty());
}

TEST_CASE(
    "run_sandboxed: a file given as stdin arrives whole, from a folder the program cannot "
    "reach",
    "[sandbox]") {
    const bool isolate = GENERATE(false, true);
    CAPTURE(isolate);
    if (!can_run(isolate)) return;
    const TempFolder closed(0700);
    const fs::path archive = closed.path() / "submission.zip";
    std::string bytes(300000, '\0');
    for (std::size_t k = 0; k < bytes.size(); ++k)
        bytes[k] = static_cast<char>(k * 7 % 251);
    std::ofstream(archive, std::ios::binary) << bytes;
    fs::permissions(archive, fs::perms::owner_read | fs::perms::owner_write);

    SandboxPolicy policy = test_policy(isolate);
    policy.stdin_file = archive;
    const HostileRun run = run_hostile({hostile("echo")}, "", policy);
    CHECK(run.run.exit_code == 0);
    CHECK(run.run.output == bytes);

    if (!files_protected(isolate)) return;
    const HostileRun by_name =
        run_hostile({hostile("read_file"), archive.string()}, "", test_policy(isolate));
    CHECK(by_name.run.exit_code == 1);
}

TEST_CASE(
    "run_sandboxed: without bubblewrap, a program in a folder shut to its user still runs, "
    "through a descriptor",
    "[sandbox]") {
    if (geteuid() != 0) return;  // not root: the program keeps the grader's user, which can enter
    const TempFolder shut(0700);
    const fs::path copy = shut.path() / "echo";
    fs::copy_file(hostile("echo"), copy);
    const HostileRun run = run_hostile({copy.string()}, "through a descriptor", test_policy(false));
    CHECK(run.run.exit_code == 0);
    CHECK(run.run.output == "through a descriptor");

    // By its name, the same user gets nowhere.
    const HostileRun by_name =
        run_hostile({hostile("read_file"), copy.string()}, "", test_policy(false));
    CHECK(by_name.run.exit_code == 1);
    CHECK(by_name.run.output.find("Permission denied") != std::string::npos);
}
