#include "grader/grade/probe_client.h"

#include <sstream>

#include "app/probe/call_reply.h"

namespace raystep::grade {

namespace {

// What the submission prints on stdout is kept to this: it is shown to the student, never read
// as an answer.
constexpr std::size_t kPrintedBytes = 1u << 20;

}  // namespace

ProbeSession ask_probe(const std::filesystem::path& program, const std::vector<ProbeQuery>& queries,
                       const ProbeRunLimits& limits) {
    // One line per query, the arguments written in place rather than copied into a line object:
    // some queries carry thousands of triangles.
    std::string input;
    for (std::size_t k = 0; k < queries.size(); ++k) {
        input += R"({"id":)" + std::to_string(k) + R"(,"call":)" +
                 probe::Json(queries[k].call).dump() + R"(,"args":)" + queries[k].args.dump() +
                 "}\n";
    }
    SandboxPolicy policy;
    policy.read_only = limits.readable;
    policy.read_only.push_back(program.parent_path());
    std::vector<std::string> argv = {program.string()};
    if (!limits.image_library.empty()) {
        argv.insert(argv.end(), {"--image-library", limits.image_library.string()});
        policy.read_only.push_back(limits.image_library.parent_path());
    }
    policy.limits.cpu_seconds = limits.cpu_seconds;
    policy.limits.wall = limits.wall;
    policy.limits.answer_bytes = limits.answer_bytes;
    policy.limits.output_bytes = kPrintedBytes;
    policy.limits.file_size_bytes = 0;  // a probe writes nothing but its answers
    policy.answer_channel = true;
    policy.input_after_first_answer = true;
    policy.single_process = true;

    ProbeSession session;
    session.run = run_sandboxed(argv, input, policy);
    session.answers.resize(queries.size());

    // Answers come in order, one per line, on the answer channel; each must carry its query's id.
    // A line out of order or unreadable is malformed; whatever the probe did not reach stays
    // unanswered.
    // The probe's main says it is ready before the queries are sent; a first line that is not
    // that was written by something else, and so is every line after it that claims an answer.
    const std::string& answers = session.run.answers;
    std::istringstream lines(answers);
    std::string first;
    if (!std::getline(lines, first) || lines.eof()) return session;
    if (first != probe::kReadyLine) {
        for (ProbeAnswer& answer : session.answers) {
            answer = probe::malformed_reply(first,
                                            "the answer channel (descriptor 3) did not start with "
                                            "the probe's ready line: something other than the "
                                            "probe wrote on it");
        }
        return session;
    }
    std::size_t next = 0;
    for (std::string line; next < queries.size() && std::getline(lines, line);) {
        if (lines.eof() && answers.back() != '\n') break;  // cut mid-line
        ProbeAnswer& answer = session.answers[next];
        if (probe::nested_too_deep(line)) {
            answer = probe::malformed_reply(
                line, "nested deeper than " + std::to_string(probe::kDeepestNesting) +
                          " levels, which no answer of the protocol is");
            ++next;
            continue;
        }
        try {
            const probe::Json parsed = probe::Json::parse(line);
            if (!parsed.is_object() || parsed.value("id", probe::Json()) != probe::Json(next)) {
                answer = probe::malformed_reply(line,
                                                "not the answer to query " + std::to_string(next) +
                                                    ": something other than the probe wrote on its "
                                                    "answer channel (descriptor 3)");
            } else {
                answer = probe::read_reply(parsed, line);
            }
        } catch (const std::exception&) {
            answer = probe::malformed_reply(line,
                                            "not JSON: something other than the probe wrote on its "
                                            "answer channel (descriptor 3)");
        }
        ++next;
    }
    return session;
}

}  // namespace raystep::grade
