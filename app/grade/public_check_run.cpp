#include "app/grade/public_check_run.h"

#include <algorithm>
#include <chrono>
#include <optional>

#include "app/grade/data_judge.h"
#include "app/probe/call_reply.h"

namespace raystep::grade {

namespace {

// As many counterexamples as the grader keeps per check.
constexpr std::size_t kCounterexamples = 5;

// The answer as a report writes it when the judge said nothing of it.
std::string answer_text(const ProbeAnswer& answer) {
    switch (answer.kind) {
        case ProbeAnswer::Kind::result:
            return answer.value.dump(-1, ' ', false, probe::Json::error_handler_t::replace);
        case ProbeAnswer::Kind::not_implemented:
            return "not implemented: " + answer.message;
        case ProbeAnswer::Kind::threw:
            return "threw " + answer.exception_type + ": " + answer.message;
        case ProbeAnswer::Kind::unanswered:
        case ProbeAnswer::Kind::malformed:
            break;
    }
    return answer.message;
}

// "stage 1: dot is not implemented yet, see ..." gives "dot"; the whole message otherwise.
std::string stub_function(const std::string& message) {
    const std::size_t colon = message.find(": ");
    const std::size_t tail = message.find(" is not implemented");
    if (colon == std::string::npos || tail == std::string::npos || tail <= colon + 2) {
        return message;
    }
    return message.substr(colon + 2, tail - colon - 2);
}

// The query with a relative scene file taken from under `root`.
ProbeQuery rooted(ProbeQuery query, const std::filesystem::path& root) {
    if (query.args.is_object() && query.args.contains("scene") && query.args["scene"].is_string()) {
        const std::filesystem::path scene = query.args["scene"].get<std::string>();
        if (scene.is_relative()) query.args["scene"] = (root / scene).string();
    }
    return query;
}

}  // namespace

CheckResult run_public_check(const PublicCheck& check, const Rubric& rubric,
                             const probe::CallTable& calls, const std::filesystem::path& root) {
    const auto start = std::chrono::steady_clock::now();
    const bool sample = check.kind == kSampleKind;
    const RubricEntry entry = sample ? RubricEntry{} : rubric.entry(check.id);

    std::size_t passed = 0;
    std::size_t stubs = 0;
    std::vector<std::string> stub_functions;  // in the order first met
    std::vector<Counterexample> wrong_answers;
    std::vector<Counterexample> stub_answers;
    std::optional<double> measured;  // a measuring judge's share, for a check of one case
    std::string measured_summary;
    for (const PublicCase& c : check.cases) {
        const ProbeAnswer answer = probe::answer_in_process(calls, rooted(c.query, root));
        Verdict verdict;
        try {
            verdict = build_judge(c.judge)(answer);
        } catch (const std::exception& error) {
            verdict.passed = false;
            verdict.expected = "an answer in the protocol's form";
            verdict.got = std::string("unreadable: ") + error.what();
        }
        if (verdict.fraction && check.cases.size() == 1) {
            measured = verdict.fraction;
            measured_summary = verdict.summary;
        }
        std::string stub = verdict.not_implemented;
        if (answer.kind == ProbeAnswer::Kind::not_implemented) stub = answer.message;
        if (verdict.passed && stub.empty()) {
            ++passed;
            continue;
        }
        if (!stub.empty()) {
            ++stubs;
            const std::string function = stub_function(stub);
            if (std::find(stub_functions.begin(), stub_functions.end(), function) ==
                stub_functions.end()) {
                stub_functions.push_back(function);
            }
        }
        std::vector<Counterexample>& kept = stub.empty() ? wrong_answers : stub_answers;
        if (kept.size() < kCounterexamples) {
            const std::string got = !stub.empty()         ? "not implemented: " + stub
                                    : verdict.got.empty() ? answer_text(answer)
                                                          : verdict.got;
            kept.push_back({verdict.place.empty() ? c.input : verdict.place, verdict.expected, got,
                            "", verdict.place.empty() ? c.reproduce : verdict.place_reproduce});
        }
    }
    std::vector<Counterexample> counterexamples = wrong_answers;
    for (const Counterexample& example : stub_answers) {
        if (counterexamples.size() == kCounterexamples) break;
        counterexamples.push_back(example);
    }

    const std::size_t total = check.cases.size();
    const Outcome outcome = total > 0 && stubs == total    ? Outcome::not_implemented
                            : total > 0 && passed == total ? Outcome::passed
                                                           : Outcome::failed;
    const double fraction = measured     ? *measured
                            : total == 0 ? 0.0
                                         : static_cast<double>(passed) / static_cast<double>(total);
    CheckResult result = scored_check(check.id, check.stage, check.kind, check.name, entry, outcome,
                                      fraction, total > 0);
    result.counterexamples = std::move(counterexamples);
    result.metrics["cases"] = static_cast<double>(total);
    result.metrics["passed"] = static_cast<double>(passed);
    std::string stub_list;
    for (const std::string& function : stub_functions)
        stub_list += (stub_list.empty() ? "" : ", ") + function;
    if (total == 0) {
        result.summary = "the case file has no cases";
    } else if (stubs == total) {
        result.summary = "not implemented: " + stub_list;
    } else if (measured) {
        result.summary = measured_summary;
    } else {
        result.summary = std::to_string(passed) + " of " + std::to_string(total) + " cases right";
        if (!stub_list.empty()) result.summary += "; not implemented: " + stub_list;
        if (sample) {
            result.summary +=
                "; a sample of the generated cases, no points (the grader's are "
                "others of the same kind)";
        }
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace raystep::grade
