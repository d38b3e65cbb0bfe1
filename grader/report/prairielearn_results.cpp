#include "grader/report/prairielearn_results.h"

#include <algorithm>
#include <map>
#include <set>

#include "grader/report/audience.h"
#include "grader/report/check_findings.h"
#include "grader/report/console_summary.h"
#include "grader/report/report_text.h"

namespace raystep::grade {

namespace {

// PrairieLearn refuses a results.json over 1 MB. The tests' outputs share 800 KB, which leaves
// room for their fields, the stage table and the JSON around them; each gets at least 1 KB
// (its summary and a counterexample) and at most 16 KB (more than anyone reads in a box).
constexpr std::size_t kOutputBudgetBytes = 800'000;
constexpr std::size_t kMinTestOutputBytes = 1'000;
constexpr std::size_t kMaxTestOutputBytes = 16'000;

bool nothing_compiled(const GradeReport& report) {
    return !report.checks.empty() &&
           std::all_of(report.checks.begin(), report.checks.end(), [](const CheckResult& check) {
               return check.outcome == Outcome::did_not_compile;
           });
}

// The compilers' first lines from the checks a student is shown, each text once: every check of
// a stage that did not compile carries the same output.
nlohmann::json format_errors(const GradeReport& report) {
    nlohmann::json errors = nlohmann::json::array();
    std::set<std::string> seen;
    for (const CheckResult& check : report.checks) {
        if (!shown_to(check, Audience::student) || check.details.empty()) continue;
        const std::string text = clipped_text(check.details, kMaxDetailsBytes);
        if (seen.insert(text).second) errors.push_back(text);
    }
    return errors;
}

// The checks of one stage that a student is not shown, summed.
struct WithheldChecks {
    double points = 0.0;
    double max_points = 0.0;
    int count = 0;
};

nlohmann::json test_of(const CheckResult& check, std::size_t max_output_bytes) {
    std::string message = outcome_name(check.outcome);
    if (!check.summary.empty()) message += ": " + clipped_text(check.summary, kMaxFieldBytes);
    return {
        {"name", displayable_text(check.id)},
        {"description", displayable_text(check.name)},
        {"points", check.score},
        {"max_points", check.max_score},
        {"message", message},
        {"output", check_findings(check, max_output_bytes)},
    };
}

}  // namespace

nlohmann::json prairielearn_results(const GradeReport& report) {
    const double total = report.score();
    const double max_total = report.max_score();
    // Rounding in the sums must not put a perfect score a hair outside [0, 1].
    const double score = max_total > 0.0 ? std::clamp(total / max_total, 0.0, 1.0) : 0.0;

    nlohmann::json results = {
        {"gradable", !nothing_compiled(report)},
        {"score", score},
        {"message", "raystep: " + score_out_of(total, max_total) + " points"},
        {"output", stage_table(report)},
    };
    if (nothing_compiled(report)) {
        results["format_errors"] = format_errors(report);
        return results;
    }

    const std::size_t shown = seen_by(report, Audience::student).checks.size();
    const std::size_t share = std::clamp(kOutputBudgetBytes / std::max<std::size_t>(shown, 1),
                                         kMinTestOutputBytes, kMaxTestOutputBytes);
    nlohmann::json tests = nlohmann::json::array();
    std::map<int, WithheldChecks> withheld;
    for (const CheckResult& check : report.checks) {
        if (shown_to(check, Audience::student)) {
            tests.push_back(test_of(check, share));
            continue;
        }
        WithheldChecks& sums = withheld[check.stage];
        sums.points += check.score;
        sums.max_points += check.max_score;
        ++sums.count;
    }
    for (const auto& [stage, sums] : withheld) {
        tests.push_back({
            {"name", stage_label(stage) + ": hidden checks"},
            {"description", sums.count == 1 ? "1 check whose name and inputs are not shown"
                                            : std::to_string(sums.count) +
                                                  " checks whose names and inputs are not shown"},
            {"points", sums.points},
            {"max_points", sums.max_points},
            {"message", score_out_of(sums.points, sums.max_points) + " points"},
            {"output", ""},
        });
    }
    results["tests"] = tests;
    return results;
}

}  // namespace raystep::grade
