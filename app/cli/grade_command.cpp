// `raystep grade [--stage N]`: the grader's public checks, run on this build in process, scored by
// the rubric and reported in the student's layout of the real grade (app/report/console_summary.h).
// A student release holds the checks as data (grading/public/*.json and grading/rubric.json,
// written by `raystep-grade release`): each case's query, its expected answer and tolerance, as
// the reference's oracle decided them, never the oracle; stage 3's functions run on the case files
// of `raystep check`, each scored against the reference's count
// (grading/3_intersect/case_file_judges.h). The hidden checks, the generated ones and the speed
// checks are not run, and the report says which and what they are worth.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "app/cli/command_registry.h"
#include "app/demo/source_tree.h"
#include "app/grade/public_case.h"
#include "app/grade/public_check_run.h"
#include "app/grade/rubric.h"
#include "app/report/console_summary.h"
#include "app/report/grade_report.h"
#include "app/report/report_text.h"
#include "base/errors/input_error.h"
#include "grading/3_intersect/case_file_judges.h"

namespace raystep {

namespace {

namespace fs = std::filesystem;
using namespace raystep::grade;

struct GradeArguments {
    int stage = -1;  ///< -1: every stage; 0: the whole pipeline
    std::string grading = (source_tree() / "grading").string();
};

// The rubric's id prefix for a stage: "stage3." or, for the pipeline, "pipeline.".
std::string id_prefix(int stage) {
    return stage == 0 ? "pipeline." : "stage" + std::to_string(stage) + ".";
}

bool selected(const GradeArguments& arguments, const std::string& id) {
    return arguments.stage < 0 || id.rfind(id_prefix(arguments.stage), 0) == 0;
}

// What the rubric holds for the stages asked that this build does not run: each id with its
// points, and the sum; said before the summary and again after it, so that neither a glance at
// the top nor at the total misses it.
std::string not_run_text(const Rubric& rubric, const std::set<std::string>& run,
                         const GradeArguments& arguments, const std::string& where) {
    std::string ids;
    double points = 0;
    int count = 0;
    for (const auto& [id, entry] : rubric.checks) {
        if (!selected(arguments, id) || run.count(id)) continue;
        ids += (ids.empty() ? "" : ", ") + id + " (" + score_text(entry.points) + ")";
        points += entry.points;
        ++count;
    }
    const bool samples = std::any_of(run.begin(), run.end(), [](const std::string& id) {
        return id.size() > 7 && id.compare(id.size() - 7, 7, ".sample") == 0;
    });
    const std::string sample_text =
        samples ? " A stage's sample (stageN.sample) is a few generated cases of the kinds its "
                  "oracle check draws, decided by the same oracle but not the grader's own cases, "
                  "and worth no points."
                : "";
    if (count == 0) return "Every check of the rubric for these stages ran here." + sample_text;
    return "Hidden checks exist and are not run here: " + std::to_string(count) +
           (count == 1 ? " check worth " : " checks worth ") + score_text(points) +
           " points run only in the grader (hidden cases, generated cases against its oracle, "
           "speed, and the hand-worked cases of the checks this release holds no case file "
           "for): " +
           ids + ". The total " + where + " counts the checks run here alone." + sample_text;
}

// The reference's count of stage-3 cases right per function, as the release writer wrote it.
std::map<std::string, std::size_t> read_stage3_reference(const fs::path& file) {
    std::ifstream in(file);
    if (!in) throw InputError(file.string(), 0, "cannot be read; the release writer makes it");
    try {
        return probe::Json::parse(in).get<std::map<std::string, std::size_t>>();
    } catch (const std::exception& error) {
        throw InputError(file.string(), 0, error.what());
    }
}

int run_grade(const GradeArguments& arguments) {
    const fs::path folder = arguments.grading;
    const fs::path public_folder = folder / "public";
    std::vector<fs::path> files;
    if (fs::is_directory(public_folder)) {
        for (const auto& entry : fs::directory_iterator(public_folder)) {
            if (entry.path().extension() == ".json") files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    if (files.empty() || !fs::exists(folder / "rubric.json")) {
        std::fprintf(stderr,
                     "raystep grade: no public case files in %s (public/*.json and rubric.json): "
                     "the release writer, `raystep-grade release`, makes them in a student "
                     "release; the instructor's repository has none\n",
                     folder.string().c_str());
        return 2;
    }
    try {
        const Rubric rubric = load_rubric(folder / "rubric.json");
        const probe::CallTable calls = probe::stage_calls();
        GradeReport report;
        report.student = "the public checks on this build";
        std::set<std::string> run;
        for (const fs::path& file : files) {
            // A case file is named for its check: those of other stages are not even read.
            if (!selected(arguments, file.stem().string())) continue;
            const PublicCheck check = read_public_check(file);
            run.insert(check.id);
            report.checks.push_back(run_public_check(check, rubric, calls, source_tree()));
        }
        // Stage 3's public cases are the case files `raystep check` reads, scored per function.
        if (selected(arguments, "stage3.")) {
            const std::vector<CaseFamily> families = stage3_public_families(source_tree());
            const std::map<std::string, std::size_t> reference =
                read_stage3_reference(folder / "stage3-reference.json");
            for (CheckResult& result : run_stage3_case_checks(families, reference, rubric)) {
                run.insert(result.id);
                report.checks.push_back(std::move(result));
            }
        }
        // Each stage's checks in the order of the rubric's kinds, its sample of generated cases
        // after the checks that carry points.
        std::stable_sort(report.checks.begin(), report.checks.end(),
                         [](const CheckResult& a, const CheckResult& b) {
                             return std::make_pair(a.stage, a.kind == kSampleKind) <
                                    std::make_pair(b.stage, b.kind == kSampleKind);
                         });
        if (report.checks.empty()) {
            std::fprintf(stderr, "raystep grade: %s has no public check for stage %d\n",
                         public_folder.string().c_str(), arguments.stage);
            return 2;
        }
        std::printf("%s\n%s\n%s",
                    console_paragraph(not_run_text(rubric, run, arguments, "below")).c_str(),
                    console_summary(report, Audience::student).c_str(),
                    console_paragraph(not_run_text(rubric, run, arguments, "above")).c_str());
        // Every check passed: each earned all its points (the grader's "passed").
        const bool all_passed =
            std::all_of(report.checks.begin(), report.checks.end(),
                        [](const CheckResult& c) { return c.outcome == Outcome::passed; });
        return all_passed ? 0 : 1;
    } catch (const InputError& error) {
        std::fprintf(stderr, "%s\n", error.what());
    } catch (const std::exception& error) {
        std::fprintf(stderr, "raystep grade: %s\n", error.what());
    }
    return 2;
}

AddedCommand add_grade(CLI::App& app) {
    auto arguments = std::make_shared<GradeArguments>();
    CLI::App* command = app.add_subcommand(
        "grade",
        "Run the grader's public checks on this build and score them by the rubric (the hidden "
        "and generated checks are not run)");
    command->add_option("--stage", arguments->stage, "Only this stage's checks (0: the pipeline)")
        ->check(CLI::Range(0, kLastStage));
    command
        ->add_option("--grading", arguments->grading,
                     "The folder of public case files and rubric (the release's grading/)")
        ->check(CLI::ExistingDirectory);
    return {command, [arguments] { return run_grade(*arguments); }};
}

const CommandRegistry::Registration kGradeCommand(add_grade);

}  // namespace

}  // namespace raystep
