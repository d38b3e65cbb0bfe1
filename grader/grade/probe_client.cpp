#include "grader/grade/probe_client.h"

#include <sstream>

namespace raystep::grade {

namespace {

ProbeAnswer read_answer(const probe::Json& line) {
    ProbeAnswer answer;
    answer.kind = ProbeAnswer::Kind::malformed;
    if (!line.is_object()) return answer;
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
    }
    return answer;
}

}  // namespace

ProbeSession ask_probe(const std::filesystem::path& program, const std::vector<ProbeQuery>& queries,
                       const ProbeRunLimits& limits) {
    std::string input;
    for (std::size_t k = 0; k < queries.size(); ++k) {
        input += probe::Json{{"id", k}, {"call", queries[k].call}, {"args", queries[k].args}}.dump();
        input += '\n';
    }
    SandboxPolicy policy;
    policy.read_only = limits.readable;
    policy.read_only.push_back(program.parent_path());
    policy.limits.cpu_seconds = limits.cpu_seconds;
    policy.limits.wall = limits.wall;
    policy.limits.output_bytes = limits.output_bytes;
    policy.limits.file_size_bytes = 0;  // a probe writes nothing but its answers

    ProbeSession session;
    session.run = run_sandboxed({program.string()}, input, policy);
    session.answers.resize(queries.size());

    // Answers come in order, one per line; each must carry its query's id. A line out of order or
    // unreadable is malformed; whatever the probe did not reach stays unanswered.
    std::istringstream lines(session.run.output);
    std::size_t next = 0;
    for (std::string line; next < queries.size() && std::getline(lines, line);) {
        if (lines.eof() && session.run.output.back() != '\n') break;  // cut mid-line
        try {
            const probe::Json parsed = probe::Json::parse(line);
            if (!parsed.is_object() || parsed.value("id", probe::Json()) != probe::Json(next)) {
                session.answers[next++].kind = ProbeAnswer::Kind::malformed;
                continue;
            }
            session.answers[next++] = read_answer(parsed);
        } catch (const std::exception&) {
            session.answers[next++].kind = ProbeAnswer::Kind::malformed;
        }
    }
    return session;
}

}  // namespace raystep::grade
