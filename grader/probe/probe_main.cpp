// raystep-probe: the untrusted half of grading (ARCHITECTURE.md, "The grader"). Built
// from a submission's files and the reference for the rest, it runs in a sandbox, reads one query
// per line on stdin and writes one answer per line on its answer channel, in order, flushing each.
// It holds no expected answer and judges nothing: raystep-grade does, from outside.
// grader/probe/README.md describes the protocol.

#include <csignal>
#include <cstdio>
#include <iostream>
#include <string>

#include <fcntl.h>
#include <unistd.h>

#include "app/probe/call_reply.h"
#include "base/image/image_library_loader.h"
#include "grading/4_accel/accel_workloads.h"

using namespace raystep;
using namespace raystep::probe;

namespace {

CallTable all_calls() {
    CallTable table = stage_calls();
    add_calls(table, accel_workload_calls);
    return table;
}

// Where the answers go. Under raystep-grade, the answer channel: descriptor 3, a pipe the grader
// opened before this program's first instruction (grader/sandbox/sandbox.h). It is moved to a
// close-on-exec descriptor and 3 is closed, so that nothing the submission runs later can write
// to it by that number, and no program it starts inherits it. stdout stays the submission's own:
// what it prints, before main or after, is shown to the student and never read as an answer.
// Run by hand, with no descriptor 3, the probe answers on stdout and sends what the submission
// prints to stderr.
std::FILE* answer_stream() {
    constexpr int kAnswerChannel = 3;
    if (fcntl(kAnswerChannel, F_GETFD) >= 0) {
        const int answers = fcntl(kAnswerChannel, F_DUPFD_CLOEXEC, 10);
        if (answers < 0 || close(kAnswerChannel) != 0) return nullptr;
        return fdopen(answers, "w");
    }
    const int answers = dup(STDOUT_FILENO);
    if (answers < 0 || dup2(STDERR_FILENO, STDOUT_FILENO) < 0) return nullptr;
    return fdopen(answers, "w");
}

// In bubblewrap a probe is its PID namespace's first process (grader/sandbox/sandbox.h), and the
// kernel delivers that process no signal it has no handler for, so abort() (a failed assert, an
// uncaught exception) could not end it with SIGABRT: the C library would fall back to a fault, and
// the report would say SIGSEGV. This handler ends it as SIGABRT would be reported, with exit code
// 128 + SIGABRT, which the sandbox reads as that signal. Installed before the submission's static
// constructors run (priority 101 comes before every default one), so that their aborts are named
// too.
__attribute__((constructor(101))) void report_abort_as_first_process() {
    if (getpid() != 1) return;
    std::signal(SIGABRT, [](int) { _exit(128 + SIGABRT); });
}

}  // namespace

// `raystep-probe [--image-library MODULE]`: the image library module a scene's textures load
// through, where raystep-grade placed a copy the sandbox's user can read (ProbeSet::image_library).
int main(int argc, char** argv) {
    if (argc == 3 && std::string(argv[1]) == "--image-library") {
        use_image_library_module(argv[2]);
    } else if (argc != 1) {
        std::fputs("usage: raystep-probe [--image-library MODULE]\n", stderr);
        return 2;
    }
    std::FILE* const answers = answer_stream();
    if (!answers) {
        std::perror("raystep-probe: cannot set up the answer stream");
        return 2;
    }
    // Ready: the grader sends the queries only now, so none waited on stdin while the
    // submission's static constructors ran
    std::fputs(kReadyLine, answers);
    std::fputc('\n', answers);
    std::fflush(answers);
    const CallTable table = all_calls();
    // A query can be megabytes (stage 4's timed scenes); stdio's shared buffer would hand them to
    // getline a character at a time, much of a timed run's start (docs/measurements/stage4-work.md)
    std::ios::sync_with_stdio(false);
    std::string line;
    while (std::getline(std::cin, line)) {
        Json query;
        try {
            query = Json::parse(line);
        } catch (const std::exception&) {
            query = {{"call", "(a line that is not JSON)"}, {"args", nullptr}};
        }
        // Invalid UTF-8 in a message a submission threw must not stop the answer: replace it.
        const std::string text =
            reply_to(table, query).dump(-1, ' ', false, Json::error_handler_t::replace);
        std::fwrite(text.data(), 1, text.size(), answers);
        std::fputc('\n', answers);
        std::fflush(answers);
    }
    return 0;
}
