#include "grader/report/student_results.h"

#include <cmath>

#include "app/report/audience.h"
#include "app/report/report_text.h"

namespace raystep::grade {

namespace {

nlohmann::json result_field(const std::string& text) {
    return clipped_text(text, kMaxFieldBytes);
}

nlohmann::json check_of(const CheckResult& check) {
    nlohmann::json counterexamples = nlohmann::json::array();
    for (const Counterexample& example : check.counterexamples) {
        counterexamples.push_back(
            {{"input", result_field(example.input)},
             {"expected", result_field(example.expected)},
             {"got", result_field(example.got)},
             {"reproduce", result_field(reproduce_command(example, Audience::student))}});
    }
    nlohmann::json metrics = nlohmann::json::object();
    for (const auto& [name, value] : check.metrics) {
        metrics[displayable_text(name)] = std::isfinite(value) ? nlohmann::json(value) : nullptr;
    }
    return {{"id", displayable_text(check.id)},
            {"stage", check.stage},
            {"kind", displayable_text(check.kind)},
            {"name", displayable_text(check.name)},
            {"outcome", outcome_name(check.outcome)},
            {"passed", check.outcome == Outcome::passed},
            {"score", check.score},
            {"max_score", check.max_score},
            {"summary", result_field(check.summary)},
            {"seconds", check.seconds},
            {"metrics", metrics},
            {"details", clipped_text(check.details, kMaxDetailsBytes)},
            {"counterexamples", counterexamples}};
}

}  // namespace

nlohmann::json student_results(const GradeReport& report) {
    const GradeReport seen = seen_by(report, Audience::student);

    nlohmann::json stages = nlohmann::json::array();
    for (const StageTally& tally : seen.stage_tallies()) {
        stages.push_back({{"stage", tally.stage},
                          {"name", stage_label(tally.stage)},
                          {"score", tally.score},
                          {"max_score", tally.max_score},
                          {"checks", tally.checks},
                          {"passed", tally.passed}});
    }
    nlohmann::json checks = nlohmann::json::array();
    for (const CheckResult& check : seen.checks)
        checks.push_back(check_of(check));

    const PhaseTimes& times = seen.times;
    return {{"student", displayable_text(report.student)},
            {"submission", displayable_text(report.submission)},
            {"intake_problem", intake_problem_line(report.intake_problem)},
            {"score", seen.score()},
            {"max_score", seen.max_score()},
            {"checks_not_shown", report.checks.size() - seen.checks.size()},
            {"stages", stages},
            {"checks", checks},
            {"times",
             {{"intake", times.intake},
              {"build", times.build},
              {"checks", times.checks},
              {"reports", times.reports}}}};
}

}  // namespace raystep::grade
