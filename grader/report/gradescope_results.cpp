#include "grader/report/gradescope_results.h"

#include <cmath>
#include <map>

#include "app/report/audience.h"
#include "app/report/console_summary.h"
#include "app/report/report_text.h"
#include "grader/report/check_findings.h"

namespace raystep::grade {

namespace {

// Text of one test's output: Gradescope puts it in a collapsed <pre>; past a few pages nobody
// reads it, and the HTML report has everything.
constexpr std::size_t kGradescopeTestOutputBytes = 16000;

nlohmann::json gradescope_test_of(const CheckResult& check, int place_in_stage) {
    std::string output = outcome_name(check.outcome);
    if (!check.summary.empty()) output += ": " + clipped_text(check.summary, kMaxFieldBytes);
    // Gradescope shows a test's output to the student: the student's commands, never the
    // instructor's.
    const std::string findings =
        check_findings(check, Audience::student, kGradescopeTestOutputBytes);
    if (!findings.empty()) output += "\n\n" + findings;

    nlohmann::json metrics = nlohmann::json::object();
    // JSON has no NaN or infinity: such a metric is stored as null.
    for (const auto& [name, value] : check.metrics) {
        metrics[displayable_text(name)] = std::isfinite(value) ? nlohmann::json(value) : nullptr;
    }
    return {
        {"score", check.score},
        {"max_score", check.max_score},
        {"status", check.outcome == Outcome::passed ? "passed" : "failed"},
        {"name", displayable_text(check.name.empty() ? check.id : check.name)},
        {"name_format", "text"},
        {"number", std::to_string(check.stage) + "." + std::to_string(place_in_stage)},
        {"output", output},
        {"output_format", "text"},
        {"tags", {stage_label(check.stage), displayable_text(check.kind)}},
        {"visibility", visibility_name(check.visibility)},
        {"extra_data",
         {{"id", displayable_text(check.id)},
          {"outcome", outcome_name(check.outcome)},
          {"metrics", metrics}}},
    };
}

}  // namespace

nlohmann::json gradescope_results(const GradeReport& report) {
    nlohmann::json tests = nlohmann::json::array();
    std::map<int, int> placed_in_stage;
    for (const CheckResult& check : report.checks) {
        tests.push_back(gradescope_test_of(check, ++placed_in_stage[check.stage]));
    }
    const GradeReport seen = seen_by(report, Audience::student);
    std::string output = intake_problem_line(report.intake_problem);
    if (!output.empty()) output += "\n\n";
    output += stage_table(seen);
    const std::size_t withheld = report.checks.size() - seen.checks.size();
    if (withheld > 0) {
        output += "\n" + std::to_string(withheld) + (withheld == 1 ? " check is" : " checks are") +
                  " graded but not shown yet; the table leaves them out.\n";
    }
    // Gradescope shows the whole run's time to the student: the student's times, which leave out
    // the withheld checks' (seen_by).
    const PhaseTimes& times = seen.times;
    const double seconds = times.intake + times.build + times.checks + times.reports;
    return {
        {"score", report.score()},
        {"execution_time", static_cast<long>(std::ceil(seconds))},
        {"output", output},
        {"output_format", "text"},
        {"test_output_format", "text"},
        {"test_name_format", "text"},
        {"visibility", "visible"},
        {"stdout_visibility", "hidden"},
        {"tests", tests},
    };
}

}  // namespace raystep::grade
