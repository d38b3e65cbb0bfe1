#include "grader/grade/check_definition.h"

#include <algorithm>
#include <csignal>
#include <cstring>

namespace raystep::grade {

namespace {

constexpr std::size_t kCounterexamples = 5;
constexpr std::size_t kLongestText = 400;

std::string clipped(std::string text) {
    if (text.size() > kLongestText) text = text.substr(0, kLongestText) + "...";
    return text;
}

// Why a run stopped early, in words, from the sandbox's account.
std::string ending(const SandboxRun& run, std::size_t answered, std::size_t asked) {
    std::string text = "the probe answered " + std::to_string(answered) + " of " +
                       std::to_string(asked) + " queries, then ";
    if (run.timed_out) return text + "ran out of time";
    if (run.signal != 0)
        return text + "died of signal " + std::to_string(run.signal) + " (" +
               strsignal(run.signal) + ")";
    if (run.output_capped) return text + "flooded its output past the cap";
    return text + "exited with code " + std::to_string(run.exit_code);
}

}  // namespace

std::string answer_text(const ProbeAnswer& answer) {
    switch (answer.kind) {
        case ProbeAnswer::Kind::result:
            return clipped(
                answer.value.dump(-1, ' ', false, probe::Json::error_handler_t::replace));
        case ProbeAnswer::Kind::not_implemented:
            return "not implemented: " + clipped(answer.message);
        case ProbeAnswer::Kind::threw:
            return "threw " + answer.exception_type + ": " + clipped(answer.message);
        case ProbeAnswer::Kind::unanswered:
            return "no answer (the probe stopped)";
        case ProbeAnswer::Kind::malformed:
            return "an answer the protocol does not allow: " + clipped(answer.message);
    }
    return "";
}

CheckMeasure run_cases(const GradingContext& context, const std::string& check_id,
                       const BuiltProbe& probe, const std::vector<ProbeCase>& cases,
                       const ProbeRunLimits& limits) {
    CheckMeasure measure;
    if (!probe.program) {
        measure.outcome = Outcome::did_not_compile;
        measure.summary = "did not compile";
        measure.details = probe.failure;
        return measure;
    }
    // The cases asked, by their index in `cases`: all of them, or the one being reproduced.
    std::vector<std::size_t> asked;
    for (std::size_t k = 0; k < cases.size(); ++k) {
        if (!context.only_case || *context.only_case == k) asked.push_back(k);
    }
    std::vector<ProbeQuery> queries;
    for (const std::size_t k : asked)
        queries.push_back(cases[k].query);
    const ProbeSession session = ask_probe(*probe.program, queries, limits);

    std::size_t passed = 0;
    std::size_t stubs = 0;
    std::size_t answered = 0;
    std::string first_stub;
    for (std::size_t n = 0; n < asked.size(); ++n) {
        const std::size_t k = asked[n];
        const ProbeAnswer& answer = session.answers[n];
        if (answer.kind != ProbeAnswer::Kind::unanswered) ++answered;
        if (answer.kind == ProbeAnswer::Kind::not_implemented) {
            ++stubs;
            if (first_stub.empty()) first_stub = answer.message;
        }
        Judgement judgement;
        try {
            judgement = cases[k].judge(answer);
        } catch (const std::exception& error) {
            judgement = wrong("an answer in the protocol's form",
                              std::string("unreadable: ") + error.what());
        }
        if (judgement.passed) {
            ++passed;
            continue;
        }
        if (measure.counterexamples.size() < kCounterexamples) {
            measure.counterexamples.push_back(
                {cases[k].input, clipped(judgement.expected),
                 clipped(judgement.got.empty() ? answer_text(answer) : judgement.got),
                 context.reproduce + " --check " + check_id + " --case " + std::to_string(k)});
        }
    }
    const std::size_t total = asked.size();
    measure.fraction = total == 0 ? 0.0 : static_cast<double>(passed) / static_cast<double>(total);
    measure.metrics["cases"] = static_cast<double>(total);
    measure.metrics["passed"] = static_cast<double>(passed);
    measure.summary = std::to_string(passed) + " of " + std::to_string(total) + " cases right";

    if (answered < total) {
        measure.outcome = session.run.timed_out ? Outcome::timed_out : Outcome::crashed;
        measure.details = ending(session.run, answered, total);
        measure.summary += "; " + measure.details;
    } else if (stubs == total) {
        measure.outcome = Outcome::not_implemented;
        measure.summary = first_stub;
    } else {
        measure.outcome = passed == total ? Outcome::passed : Outcome::failed;
    }
    return measure;
}

}  // namespace raystep::grade
