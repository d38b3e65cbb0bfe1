#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "grader/grade/probe_builder.h"
#include "grader/grade/probe_client.h"
#include "grader/report/grade_report.h"

namespace raystep::grade {

/// What grading needs beyond the probes: where images go, the reference probe (speed checks time
/// it beside the submission's), and how a reproduce command starts.
struct GradingContext {
    const ProbeSet* probes = nullptr;
    std::filesystem::path source;            ///< the repository: scenes/ for render checks
    std::filesystem::path report_folder;     ///< render checks write their images here
    std::filesystem::path reference_probe;   ///< raystep-probe-reference
    std::string reproduce;                   ///< "raystep-grade submission PATH", to which
                                             ///< " --check ID --case N" is appended
    std::optional<std::size_t> only_case;    ///< --case N: ask the probe that case alone
};

/// What a check found, before the rubric turns it into points: `fraction` in [0, 1] is what the
/// rubric scores (cases passed, pixels matching, speed against the reference).
struct CheckMeasure {
    Outcome outcome = Outcome::failed;
    double fraction = 0.0;
    std::string summary;
    std::vector<Counterexample> counterexamples;
    std::map<std::string, double> metrics;
    RenderImages images;
    std::string details;
};

struct CheckDefinition {
    std::string id;    ///< "stage1.unit"; the rubric's key
    int stage = 0;     ///< whose probe answers it: 1 to 7, or 0 for the whole pipeline
    std::string kind;  ///< "unit", "oracle", "render", "speed"
    std::string name;
    std::function<CheckMeasure(const GradingContext&, const BuiltProbe&)> measure;
};

/// Every check, stage by stage (grader/grade/checks/).
std::vector<CheckDefinition> all_checks();

// Building blocks for checks that send cases to a probe and judge each answer.

/// How one answer compares with the grader's expectation: passed, or what was expected and got.
struct Judgement {
    bool passed = false;
    std::string expected;
    std::string got;
};

inline Judgement right() {
    return {true, "", ""};
}
inline Judgement wrong(std::string expected, std::string got) {
    return {false, std::move(expected), std::move(got)};
}

/// One case of a check: what the probe is asked, and how its answer is judged. The judge sees
/// only the probe's answer; the expectation lives in the grader, in the judge.
struct ProbeCase {
    std::string input;  ///< the case, readable, for the report
    ProbeQuery query;
    std::function<Judgement(const ProbeAnswer&)> judge;
};

/// Asks the probe every case in one run (only context.only_case, when set) and judges the answers. The outcome: did_not_compile
/// without a probe; not_implemented when every answer is a stub's; timed_out or crashed when the
/// run ended before answering everything (with the sandbox's account in details); passed when
/// every case passed, else failed. `fraction` is the share of cases passed (unanswered ones and
/// stubs' count as failed). Keeps the first few counterexamples.
CheckMeasure run_cases(const GradingContext& context, const std::string& check_id,
                       const BuiltProbe& probe, const std::vector<ProbeCase>& cases,
                       const ProbeRunLimits& limits = {});

/// The answer's text for a report: the result's JSON, or what was thrown, or why there is none.
std::string answer_text(const ProbeAnswer& answer);

}  // namespace raystep::grade
