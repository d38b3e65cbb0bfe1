// raystep-probe: the untrusted half of grading (ARCHITECTURE.md, "The grader"). Built
// from a submission's files and the reference for the rest, it runs in a sandbox, reads one query
// per line on stdin and writes one answer per line on its answer channel, in order, flushing each.
// It holds no expected answer and judges nothing: raystep-grade does, from outside.
// grader/probe/README.md describes the protocol.

#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <typeinfo>

#include <fcntl.h>
#include <unistd.h>

#include "base/errors/not_implemented.h"
#include "grader/probe/call_table.h"

using namespace raystep;
using namespace raystep::probe;

namespace {

CallTable all_calls() {
    CallTable table;
    add_vector_calls(table);
    add_ray_calls(table);
    add_intersect_calls(table);
    add_accel_calls(table);
    add_transform_calls(table);
    add_shading_calls(table);
    add_recursion_calls(table);
    add_render_calls(table);
    return table;
}

// The standard exceptions the contracts name, by name; anything else is "other".
std::string exception_type(const std::exception& error) {
    if (dynamic_cast<const std::domain_error*>(&error)) return "domain_error";
    if (dynamic_cast<const std::invalid_argument*>(&error)) return "invalid_argument";
    if (dynamic_cast<const std::out_of_range*>(&error)) return "out_of_range";
    if (dynamic_cast<const std::logic_error*>(&error)) return "logic_error";
    if (dynamic_cast<const std::runtime_error*>(&error)) return "runtime_error";
    return "other";
}

Json answer(const CallTable& table, const Json& query) {
    Json reply = {{"id", query.value("id", Json(nullptr))}};
    try {
        const std::string name = query.at("call").get<std::string>();
        const auto call = table.find(name);
        if (call == table.end()) throw std::invalid_argument("the probe has no call " + name);
        reply["result"] = call->second(query.at("args"));
    } catch (const NotImplemented& stub) {
        reply["not_implemented"] = stub.what();
    } catch (const std::exception& error) {
        reply["threw"] = {{"type", exception_type(error)}, {"message", error.what()}};
    } catch (...) {
        reply["threw"] = {{"type", "other"},
                          {"message", "a thrown value that is not a std::exception"}};
    }
    return reply;
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

}  // namespace

int main() {
    std::FILE* const answers = answer_stream();
    if (!answers) {
        std::perror("raystep-probe: cannot set up the answer stream");
        return 2;
    }
    const CallTable table = all_calls();
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
            answer(table, query).dump(-1, ' ', false, Json::error_handler_t::replace);
        std::fwrite(text.data(), 1, text.size(), answers);
        std::fputc('\n', answers);
        std::fflush(answers);
    }
    return 0;
}
