#include "grader/grade/check_definition.h"

#include <algorithm>
#include <csignal>
#include <cstring>
#include <random>

namespace raystep::grade {

namespace {

constexpr std::size_t kCounterexamples = 5;
constexpr std::size_t kLongestText = 400;
// A summary names at most this many functions that are stubs: every function of a stage fits.
constexpr std::size_t kStubNames = 10;

std::string clipped(std::string text) {
    if (text.size() > kLongestText) text = text.substr(0, kLongestText) + "...";
    return text;
}

// Why a run stopped early, in words, from the sandbox's account.
std::string ending(const SandboxRun& run, std::size_t answered, std::size_t asked) {
    std::string text = "the probe answered " + std::to_string(answered) + " of " +
                       std::to_string(asked) + " queries, then ";
    if (run.timed_out) return text + "ran out of time";
    if (run.signal != 0) {
        const std::string limit = limit_of_signal(run.signal);
        return text + "died of signal " + std::to_string(run.signal) + " (" +
               strsignal(run.signal) + ")" + (limit.empty() ? "" : ": " + limit);
    }
    if (run.answers_capped) return text + "flooded its answer channel past the cap";
    return text + "exited with code " + std::to_string(run.exit_code);
}

// --case N beyond the check's cases: nothing was asked, and the summary says why.
void say_no_such_case(CheckMeasure& measure, std::size_t asked_for, std::size_t count) {
    measure.summary = "grader error: there is no case " + std::to_string(asked_for) +
                      "; the check has " + std::to_string(count) + " cases";
}

// One case's part of a batch's answer: its element of the list, or the whole answer when there
// is no list (a stub, an exception, no answer). A list of the wrong length answers no case.
ProbeAnswer element_of(const ProbeAnswer& whole, std::size_t element, std::size_t count) {
    if (whole.kind != ProbeAnswer::Kind::result) return whole;
    ProbeAnswer part;
    if (!whole.value.is_array() || whole.value.size() != count) {
        part.kind = ProbeAnswer::Kind::malformed;
        return part;
    }
    part.kind = ProbeAnswer::Kind::result;
    part.value = whole.value[element];
    return part;
}

}  // namespace

CheckMeasure not_compiled(const BuiltProbe& probe) {
    CheckMeasure measure;
    measure.outcome = Outcome::did_not_compile;
    measure.summary = "did not compile";
    measure.details = probe.failure;
    return measure;
}

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

std::string stub_function(const std::string& message) {
    // NotImplemented's text: "stage N: FUNCTION is not implemented yet, see ..."
    const std::size_t colon = message.find(": ");
    const std::size_t tail = message.find(" is not implemented");
    if (colon == std::string::npos || tail == std::string::npos || tail <= colon + 2) {
        return clipped(message);
    }
    return clipped(message.substr(colon + 2, tail - colon - 2));
}

CheckMeasure run_cases(const GradingContext& context, const std::string& check_id,
                       const BuiltProbe& probe, const std::vector<ProbeCase>& cases,
                       const ProbeRunLimits& limits) {
    if (!probe.program) return not_compiled(probe);
    // The cases asked, by their index in `cases`: all of them, or the one being reproduced.
    std::vector<std::size_t> asked;
    for (std::size_t k = 0; k < cases.size(); ++k) {
        if (!context.only_case || *context.only_case == k) asked.push_back(k);
    }
    std::vector<ProbeQuery> queries;
    for (const std::size_t k : asked)
        queries.push_back(cases[k].query);
    const ProbeSession session =
        asked.empty() ? ProbeSession{} : ask_probe(*probe.program, queries, limits);
    CheckMeasure measure = judge_answers(context, check_id, cases, asked, session);
    if (asked.empty() && context.only_case)
        say_no_such_case(measure, *context.only_case, cases.size());
    return measure;
}

CheckMeasure run_batched_cases(const GradingContext& context, const std::string& check_id,
                               const BuiltProbe& probe, const std::vector<CaseBatch>& batches,
                               const ProbeRunLimits& limits) {
    if (!probe.program) return not_compiled(probe);
    // The cases numbered across the batches, and where each sits: batch and element.
    std::vector<ProbeCase> cases;
    std::vector<std::pair<std::size_t, std::size_t>> place;
    for (std::size_t b = 0; b < batches.size(); ++b) {
        for (std::size_t e = 0; e < batches[b].cases.size(); ++e) {
            cases.push_back(batches[b].cases[e]);
            place.push_back({b, e});
        }
    }
    std::vector<std::size_t> asked;
    ProbeSession answers;
    if (context.only_case) {
        const std::size_t k = *context.only_case;
        if (k < cases.size()) {
            asked.push_back(k);
            const auto [b, e] = place[k];
            const ProbeSession session =
                ask_probe(*probe.program, {batches[b].one_case(e)}, limits);
            answers.run = session.run;
            answers.answers.push_back(element_of(session.answers.front(), 0, 1));
        }
    } else {
        std::vector<ProbeQuery> queries;
        for (const CaseBatch& batch : batches)
            queries.push_back(batch.query);
        const ProbeSession session =
            queries.empty() ? ProbeSession{} : ask_probe(*probe.program, queries, limits);
        answers.run = session.run;
        for (std::size_t k = 0; k < cases.size(); ++k) {
            const auto [b, e] = place[k];
            asked.push_back(k);
            answers.answers.push_back(element_of(session.answers[b], e, batches[b].cases.size()));
        }
    }
    CheckMeasure measure = judge_answers(context, check_id, cases, asked, answers);
    if (asked.empty() && context.only_case)
        say_no_such_case(measure, *context.only_case, cases.size());
    return measure;
}

CheckMeasure judge_answers(const GradingContext& context, const std::string& check_id,
                           const std::vector<ProbeCase>& cases,
                           const std::vector<std::size_t>& asked, const ProbeSession& session) {
    CheckMeasure measure;
    std::size_t passed = 0;
    std::size_t stubs = 0;
    std::size_t answered = 0;
    std::vector<std::string> stub_functions;  // in the order first met
    std::string first_stub;
    std::vector<Counterexample> wrong_answers;
    std::vector<Counterexample> stub_answers;
    const ProbeAnswer unanswered;
    for (std::size_t n = 0; n < asked.size(); ++n) {
        const std::size_t k = asked[n];
        const ProbeAnswer& answer = n < session.answers.size() ? session.answers[n] : unanswered;
        if (answer.kind != ProbeAnswer::Kind::unanswered) ++answered;
        Judgement judgement;
        try {
            judgement = cases[k].judge(answer);
        } catch (const std::exception& error) {
            judgement = wrong("an answer in the protocol's form",
                              std::string("unreadable: ") + error.what());
        }
        // A stub's answer is never a pass, whatever a judge makes of it.
        std::string stub_message = judgement.not_implemented;
        if (answer.kind == ProbeAnswer::Kind::not_implemented) stub_message = answer.message;
        if (judgement.passed && stub_message.empty()) {
            ++passed;
            continue;
        }
        if (!stub_message.empty()) {
            ++stubs;
            if (first_stub.empty()) first_stub = stub_message;
            const std::string function = stub_function(stub_message);
            if (std::find(stub_functions.begin(), stub_functions.end(), function) ==
                stub_functions.end()) {
                stub_functions.push_back(function);
            }
        }
        std::vector<Counterexample>& kept = stub_message.empty() ? wrong_answers : stub_answers;
        if (kept.size() < kCounterexamples) {
            const std::string got = !stub_message.empty()   ? "not implemented: " + stub_message
                                    : judgement.got.empty() ? answer_text(answer)
                                                            : judgement.got;
            kept.push_back(
                {cases[k].input, clipped(judgement.expected), clipped(got),
                 context.reproduce + " --check " + check_id + " --case " + std::to_string(k),
                 cases[k].student_reproduce});
        }
    }
    // Wrong answers say more than stubs, which the summary names anyway.
    measure.counterexamples = wrong_answers;
    for (const Counterexample& example : stub_answers) {
        if (measure.counterexamples.size() == kCounterexamples) break;
        measure.counterexamples.push_back(example);
    }

    const std::size_t total = asked.size();
    measure.metrics["cases"] = static_cast<double>(total);
    measure.metrics["passed"] = static_cast<double>(passed);
    if (total == 0) {
        // Nothing asked, nothing measured: a check that cannot fail must not pass.
        measure.grader_error = true;
        measure.outcome = Outcome::failed;
        measure.summary = "grader error: the check asked no cases";
        return measure;
    }
    measure.fraction = static_cast<double>(passed) / static_cast<double>(total);
    measure.summary = std::to_string(passed) + " of " + std::to_string(total) + " cases right";
    // The names, a few at most: student code may throw a different message for every case.
    std::string stub_list;
    for (std::size_t f = 0; f < std::min(stub_functions.size(), kStubNames); ++f) {
        stub_list += (f == 0 ? "" : ", ") + stub_functions[f];
    }
    if (stub_functions.size() > kStubNames) {
        stub_list += " and " + std::to_string(stub_functions.size() - kStubNames) + " more";
    }
    if (answered < total) {
        measure.outcome = session.run.timed_out ? Outcome::timed_out : Outcome::crashed;
        measure.details = ending(session.run, answered, total);
        measure.summary += "; " + measure.details;
        if (!stub_list.empty()) measure.summary += "; not implemented: " + stub_list;
    } else if (stubs == total) {
        measure.outcome = Outcome::not_implemented;
        measure.summary =
            stub_functions.size() == 1 ? clipped(first_stub) : "not implemented: " + stub_list;
    } else {
        measure.outcome = passed == total ? Outcome::passed : Outcome::failed;
        if (!stub_list.empty()) measure.summary += "; not implemented: " + stub_list;
    }
    return measure;
}

std::vector<std::size_t> check_start_order(const std::vector<CheckDefinition>& checks) {
    std::vector<std::size_t> order;
    for (const bool sharing : {false, true}) {
        for (std::size_t k = 0; k < checks.size(); ++k) {
            if (checks[k].kind != "speed" && checks[k].measured_by.empty() != sharing)
                order.push_back(k);
        }
    }
    return order;
}

std::uint64_t fresh_grade_seed() {
    std::random_device source;
    return (std::uint64_t{source()} << 32) ^ std::uint64_t{source()};
}

}  // namespace raystep::grade
