#include "grader/report/prairielearn_results.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string_view>

#include "app/report/audience.h"
#include "app/report/console_summary.h"
#include "app/report/report_text.h"
#include "grader/report/check_findings.h"
#include "grader/report/data_url.h"

namespace raystep::grade {

namespace {

// PrairieLearn refuses a results.json over 1 MB. The tests' outputs share 400 KB and the render
// checks' images 450 KB, which leaves room for the tests' fields, the stage table and the JSON
// around them. Each output gets at least 1 KB (its summary and a counterexample) and at most
// 16 KB (more than anyone reads in a box).
constexpr std::size_t kOutputBudgetBytes = 400'000;
constexpr std::size_t kImageBudgetBytes = 450'000;
constexpr std::size_t kMinTestOutputBytes = 1'000;
constexpr std::size_t kMaxTestOutputBytes = 16'000;

// What a test whose images did not fit says instead.
constexpr std::string_view kImagesLeftOut =
    "The images are left out here: PrairieLearn takes at most 1 MB of results. The HTML report "
    "shows them.";

bool nothing_compiled(const GradeReport& report) {
    return !report.checks.empty() &&
           std::all_of(report.checks.begin(), report.checks.end(), [](const CheckResult& check) {
               return check.outcome == Outcome::did_not_compile;
           });
}

// The intake problem, then the compilers' first lines from the checks a student is shown, each
// text once: every check of a stage that did not compile carries the same output.
nlohmann::json format_errors(const GradeReport& report) {
    nlohmann::json errors = nlohmann::json::array();
    const std::string intake_problem = intake_problem_line(report.intake_problem);
    if (!intake_problem.empty()) errors.push_back(intake_problem);
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

// A render check's images as PrairieLearn's {label, url} with data URLs, in the HTML report's
// order; the ones missing from the folder left out.
nlohmann::json images_of(const CheckResult& check, const std::filesystem::path& images_folder) {
    nlohmann::json images = nlohmann::json::array();
    const std::pair<const char*, const std::string*> labelled[] = {
        {"reference", &check.images.reference},
        {"student", &check.images.student},
        {"difference", &check.images.difference}};
    for (const auto& [label, path] : labelled) {
        if (path->empty()) continue;
        if (std::optional<std::string> url =
                image_data_url(images_folder / *path, kImageBudgetBytes)) {
            images.push_back({{"label", label}, {"url", std::move(*url)}});
        }
    }
    return images;
}

std::size_t data_bytes(const nlohmann::json& images) {
    std::size_t bytes = 0;
    for (const nlohmann::json& image : images)
        bytes += image.at("url").get_ref<const std::string&>().size();
    return bytes;
}

// The images of each check a student is shown, by its place in the report, within
// kImageBudgetBytes: first the checks that did not pass, whose images show what is wrong, then
// the others; each check's images whole or not at all. A check with images that did not fit maps
// to null.
std::map<std::size_t, nlohmann::json> images_within_budget(
    const GradeReport& report, const std::filesystem::path& images_folder) {
    std::map<std::size_t, nlohmann::json> chosen;
    std::size_t left = kImageBudgetBytes;
    for (const bool passed : {false, true}) {
        for (std::size_t k = 0; k < report.checks.size(); ++k) {
            const CheckResult& check = report.checks[k];
            if (!shown_to(check, Audience::student) ||
                (check.outcome == Outcome::passed) != passed) {
                continue;
            }
            nlohmann::json images = images_of(check, images_folder);
            if (images.empty()) continue;
            const std::size_t bytes = data_bytes(images);
            if (bytes <= left) {
                left -= bytes;
                chosen[k] = std::move(images);
            } else {
                chosen[k] = nullptr;
            }
        }
    }
    return chosen;
}

nlohmann::json prairielearn_test_of(const CheckResult& check, std::size_t max_output_bytes,
                                    const nlohmann::json* images) {
    std::string message = outcome_name(check.outcome);
    if (!check.summary.empty()) message += ": " + clipped_text(check.summary, kMaxFieldBytes);
    // PrairieLearn shows every test to the student: the student's commands, never the
    // instructor's.
    std::string output = check_findings(check, Audience::student, max_output_bytes);
    if (images != nullptr && images->is_null()) {
        output += (output.empty() ? "" : "\n\n") + std::string(kImagesLeftOut);
    }
    nlohmann::json test = {
        {"name", displayable_text(check.id)},
        {"description", displayable_text(check.name)},
        {"points", check.score},
        {"max_points", check.max_score},
        {"message", message},
        {"output", output},
    };
    if (images != nullptr && !images->is_null()) test["images"] = *images;
    return test;
}

}  // namespace

nlohmann::json prairielearn_results(const GradeReport& report,
                                    const std::filesystem::path& images_folder) {
    const double total = report.score();
    const double max_total = report.max_score();
    // Rounding in the sums must not put a perfect score a hair outside [0, 1].
    const double score = max_total > 0.0 ? std::clamp(total / max_total, 0.0, 1.0) : 0.0;

    std::string message = intake_problem_line(report.intake_problem);
    if (!message.empty()) message += "\n";
    message += "raystep: " + score_out_of(total, max_total) + " points";
    nlohmann::json results = {
        {"gradable", !nothing_compiled(report)},
        {"score", score},
        {"message", message},
        {"output", stage_table(report)},
    };
    if (nothing_compiled(report)) {
        results["format_errors"] = format_errors(report);
        return results;
    }

    const std::size_t shown = seen_by(report, Audience::student).checks.size();
    const std::size_t share = std::clamp(kOutputBudgetBytes / std::max<std::size_t>(shown, 1),
                                         kMinTestOutputBytes, kMaxTestOutputBytes);
    const std::map<std::size_t, nlohmann::json> images =
        images_within_budget(report, images_folder);
    nlohmann::json tests = nlohmann::json::array();
    std::map<int, WithheldChecks> withheld;
    for (std::size_t k = 0; k < report.checks.size(); ++k) {
        const CheckResult& check = report.checks[k];
        if (shown_to(check, Audience::student)) {
            const auto found = images.find(k);
            tests.push_back(prairielearn_test_of(check, share,
                                                 found == images.end() ? nullptr : &found->second));
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
