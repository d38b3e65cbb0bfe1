#include "grader/grade/probe_client.h"

#include <sstream>

namespace raystep::grade {

namespace {

// What the submission prints on stdout is kept to this: it is shown to the student, never read
// as an answer.
constexpr std::size_t kPrintedBytes = 1u << 20;

constexpr std::size_t kShownBytes = 200;

// What a report says of a line that is not an answer: the line itself, clipped, and the likely
// cause. Only the probe writes on the answer channel, so a line that is not its answer means the
// submission wrote there (descriptor 3) or broke the probe's own state.
ProbeAnswer malformed(const std::string& line, const std::string& cause) {
    ProbeAnswer answer;
    answer.kind = ProbeAnswer::Kind::malformed;
    const std::string shown =
        line.size() > kShownBytes ? line.substr(0, kShownBytes) + "..." : line;
    answer.message = "received \"" + shown + "\": " + cause;
    return answer;
}

ProbeAnswer read_answer(const probe::Json& line, const std::string& text) {
    ProbeAnswer answer;
    if (line.contains("result")) {
        answer.kind = ProbeAnswer::Kind::result;
        answer.value = line["result"];
    } else if (line.contains("not_implemented") && line["not_implemented"].is_string()) {
        answer.kind = ProbeAnswer::Kind::not_implemented;
        answer.message = line["not_implemented"].get<std::string>();
    } else if (line.contains("threw") && line["threw"].is_object()) {
        const probe::Json& threw = line["threw"];
        answer.kind = ProbeAnswer::Kind::threw;
        answer.exception_type = threw.value("type", "other");
        answer.message = threw.value("message", "");
    } else {
        answer = malformed(text, "an answer with neither result, not_implemented nor threw");
    }
    return answer;
}

}  // namespace

ProbeSession ask_probe(const std::filesystem::path& program, const std::vector<ProbeQuery>& queries,
                       const ProbeRunLimits& limits) {
    std::string input;
    for (std::size_t k = 0; k < queries.size(); ++k) {
        input +=
            probe::Json{{"id", k}, {"call", queries[k].call}, {"args", queries[k].args}}.dump();
        input += '\n';
    }
    SandboxPolicy policy;
    policy.read_only = limits.readable;
    policy.read_only.push_back(program.parent_path());
    policy.limits.cpu_seconds = limits.cpu_seconds;
    policy.limits.wall = limits.wall;
    policy.limits.answer_bytes = limits.answer_bytes;
    policy.limits.output_bytes = kPrintedBytes;
    policy.limits.file_size_bytes = 0;  // a probe writes nothing but its answers
    policy.answer_channel = true;

    ProbeSession session;
    session.run = run_sandboxed({program.string()}, input, policy);
    session.answers.resize(queries.size());

    // Answers come in order, one per line, on the answer channel; each must carry its query's id.
    // A line out of order or unreadable is malformed; whatever the probe did not reach stays
    // unanswered.
    const std::string& answers = session.run.answers;
    std::istringstream lines(answers);
    std::size_t next = 0;
    for (std::string line; next < queries.size() && std::getline(lines, line);) {
        if (lines.eof() && answers.back() != '\n') break;  // cut mid-line
        ProbeAnswer& answer = session.answers[next];
        try {
            const probe::Json parsed = probe::Json::parse(line);
            if (!parsed.is_object() || parsed.value("id", probe::Json()) != probe::Json(next)) {
                answer = malformed(line, "not the answer to query " + std::to_string(next) +
                                             ": something other than the probe wrote on its "
                                             "answer channel (descriptor 3)");
            } else {
                answer = read_answer(parsed, line);
            }
        } catch (const std::exception&) {
            answer = malformed(line,
                               "not JSON: something other than the probe wrote on its "
                               "answer channel (descriptor 3)");
        }
        ++next;
    }
    return session;
}

}  // namespace raystep::grade
