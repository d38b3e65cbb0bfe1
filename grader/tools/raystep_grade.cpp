// raystep-grade: the trusted half of grading (ARCHITECTURE.md, "The grader";
// docs/instructor.md). Grades one submission or a whole class, and makes the student release.
// Exit codes: 0 graded (whatever the score), 1 the grader itself failed, 2 a bad command line.

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include "app/report/audience.h"
#include "app/report/console_summary.h"
#include "app/report/grade_report.h"
#include "grader/grade/batch.h"
#include "grader/grade/build_locations.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/grade/checks/statistics_seed.h"
#include "grader/grade/grade_submission.h"
#include "grader/grade/merge_shards.h"
#include "grader/grade/release.h"
#include "grader/grade/release_grading.h"
#include "grader/grade/seed_sweep.h"
#include "grader/grade/shard.h"
#include "grader/grade/write_reports.h"
#include "grader/sandbox/sandbox.h"

using namespace raystep::grade;
namespace fs = std::filesystem;

namespace {

// Says which sandbox grades, before anything is graded: without bubblewrap the isolation is the
// machine's or container's (docs/instructor.md, "3. The sandbox: what a submission cannot do").
void print_sandbox() {
    std::printf("sandbox: %s\n",
                bubblewrap_available()
                    ? "bubblewrap (namespaces, no network, read-only view) with rlimits"
                    : "rlimits, a timeout and an output cap only: bubblewrap cannot make a "
                      "sandbox on this machine");
}

int default_jobs() {
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

struct SubmissionArguments {
    std::string path;
    std::string output = "grade-report";
    int jobs = default_jobs();
    std::string check;
    int stage = -1;
    bool no_speed = false;
    long case_index = -1;
    std::string rubric = built_rubric().string();
    bool instructor = false;
    std::string work;
    bool keep_work = false;
    std::string cache;
    std::uint64_t seed = kDefaultStatisticsSeed;
    std::optional<std::uint64_t> eye_seed;
    int checks_time_limit = kChecksTimeLimit;
};

int grade_one(const SubmissionArguments& arguments) {
    print_sandbox();
    const auto start = std::chrono::steady_clock::now();
    // Every path absolute from here on: the grader hands them to programs that run elsewhere.
    const fs::path output = fs::absolute(arguments.output);
    GradeOptions options;
    options.submission = fs::absolute(arguments.path);
    options.output = output;
    if (!arguments.work.empty()) options.work_parent = fs::absolute(arguments.work);
    options.keep_work = arguments.keep_work;
    if (!arguments.cache.empty()) options.cache = fs::absolute(arguments.cache);
    options.jobs = arguments.jobs;
    options.only_check = arguments.check;
    if (arguments.stage >= 0) options.only_stage = arguments.stage;
    options.skip_speed = arguments.no_speed;
    if (arguments.case_index >= 0)
        options.only_case = static_cast<std::size_t>(arguments.case_index);
    options.eye_seed = arguments.eye_seed;
    options.checks_time_limit = std::chrono::seconds(arguments.checks_time_limit);
    options.reference_probe = built_reference_probe();
    options.reproduce = "raystep-grade submission " + arguments.path;
    // The statistical checks' seed is part of how a case is reproduced: a command for one of
    // them names it unless it is the default.
    set_statistics_seed(arguments.seed);
    if (arguments.seed != kDefaultStatisticsSeed)
        options.reproduce += " --seed " + std::to_string(arguments.seed);
    GradeReport report = grade_submission(options, load_rubric(fs::absolute(arguments.rubric)),
                                          this_build_toolchain());
    const auto reports_start = std::chrono::steady_clock::now();
    write_reports(report, output);
    report.times.reports =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - reports_start).count();
    write_reports(report, output);  // again, with the reports' own time in report.json
    std::fputs(
        console_summary(report, arguments.instructor ? Audience::instructor : Audience::student)
            .c_str(),
        stdout);
    const double total =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "\ntimes: intake %.1f s, build %.1f s, checks %.1f s, reports %.1f s; %.1f s in all\n",
        report.times.intake, report.times.build, report.times.checks, report.times.reports, total);
    if (!report.work_folder.empty())
        std::printf("work folder kept: %s\n", report.work_folder.c_str());
    std::printf(
        "reports: %s/student/ (index.html, results.json, junit.xml: for the student), "
        "%s/instructor/ (instructor.html, results.json for Gradescope, prairielearn.json, "
        "junit.xml, report.json)\n",
        output.c_str(), output.c_str());
    return 0;
}

struct BatchArguments {
    std::string folder;
    std::string output = "grades";
    int jobs = default_jobs();
    std::string rubric = built_rubric().string();
    bool no_speed = false;
    std::string shard = "1/1";
    std::vector<std::string> merge;
    std::optional<std::uint64_t> eye_seed;
};

// batch --merge: the shards' folders put back together into one grades.csv.
int merge_many(const BatchArguments& arguments) {
    std::vector<fs::path> folders(arguments.merge.begin(), arguments.merge.end());
    const MergedClass merged = merge_shards(folders);
    write_grades_csv(merged.reports, fs::absolute(arguments.output));
    for (const std::string& warning : merged.warnings)
        std::fprintf(stderr, "raystep-grade: warning: %s\n", warning.c_str());
    std::printf("merged %zu shard folders: %zu students in %s/grades.csv%s\n", folders.size(),
                merged.reports.size(), arguments.output.c_str(),
                merged.warnings.empty() ? "" : "; see the warnings above");
    return merged.warnings.empty() ? 0 : 1;
}

int grade_many(const BatchArguments& arguments) {
    if (!arguments.merge.empty()) return merge_many(arguments);
    print_sandbox();
    BatchOptions options;
    options.folder = fs::absolute(arguments.folder);
    options.output = fs::absolute(arguments.output);
    options.jobs = arguments.jobs;
    options.skip_speed = arguments.no_speed;
    options.shard = parse_shard(arguments.shard);
    options.eye_seed = arguments.eye_seed;
    options.progress = isatty(fileno(stderr)) != 0;
    options.reference_probe = built_reference_probe();
    const auto start = std::chrono::steady_clock::now();
    const BatchTally tally =
        grade_class(options, load_rubric(fs::absolute(arguments.rubric)), this_build_toolchain());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "graded %zu submissions, %zu already graded before, %zu failed, in %.0f s; %s: "
        "%s/grades.csv\n",
        tally.graded, tally.resumed, tally.failed, seconds,
        options.shard.count > 1 ? ("shard " + options.shard.text()).c_str() : "the class",
        arguments.output.c_str());
    return tally.failed == 0 ? 0 : 1;
}

int release(const std::string& output) {
    const ReleaseSummary summary = make_release(this_build_toolchain().source, output);
    std::printf(
        "wrote the student release to %s: %zu files, %zu reference images, %zu reference "
        "traces, %zu public case files\n",
        output.c_str(), summary.files, summary.reference_images, summary.reference_traces,
        summary.public_checks);
    for (const std::string& skipped : summary.skipped)
        std::printf("  not rendered: %s\n", skipped.c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    // What the grader makes for the sandbox's user to read (the work folder's headers, sources,
    // probes) must not hang on the instructor's umask: folders 0755, files 0644 unless set.
    umask(022);
    CLI::App app{"raystep-grade: grade raystep submissions (docs/instructor.md)", "raystep-grade"};
    app.require_subcommand(1);

    SubmissionArguments one;
    CLI::App* submission =
        app.add_subcommand("submission", "Grade one submission: a folder or a .zip");
    submission->add_option("path", one.path, "The submission")
        ->required()
        ->check(CLI::ExistingPath);
    submission->add_option("-o,--output", one.output,
                           "Where the reports go (default: grade-report)");
    submission
        ->add_option("--jobs", one.jobs, "Compiles and checks at a time (default: every core)")
        ->check(CLI::Range(1, 256));
    submission->add_option("--check", one.check, "Run only this check, by id");
    submission
        ->add_option("--stage", one.stage, "Run only this stage's checks (0: the whole pipeline's)")
        ->check(CLI::Range(0, kLastStage));
    submission->add_flag("--no-speed", one.no_speed,
                         "Leave out the speed checks (on a loaded machine, or to regrade quickly)");
    submission->add_option("--case", one.case_index, "With --check: only this case")
        ->check(CLI::NonNegativeNumber);
    submission
        ->add_option("--rubric", one.rubric, "The rubric (default: grader/rubric/rubric.json)")
        ->check(CLI::ExistingFile);
    submission->add_flag("--instructor", one.instructor, "Show hidden checks on the console too");
    submission->add_option("--work", one.work,
                           "Where to build (default: beside the reports, or the system's temporary "
                           "folder where the sandbox's user cannot reach them)");
    submission->add_option("--seed", one.seed,
                           "The seed of the statistical checks (stages 8 and 10) and "
                           "of stage 3's contract cases: a right submission passes at any seed at "
                           "their stated false-fail rate");
    submission->add_option("--eye-seed", one.eye_seed,
                           "The seed of the eyes the render checks look from, as a reproduce line "
                           "names it (default: drawn anew for each grade)");
    submission
        ->add_option("--checks-time-limit", one.checks_time_limit,
                     "Seconds of wall-clock time the checks may take; a check that would start "
                     "later ends as timed out (default: " +
                         std::to_string(kChecksTimeLimit) + ")")
        ->check(CLI::Range(1, 86400));
    submission->add_flag("--keep-work", one.keep_work,
                         "Keep the build (the submission's files, objects, probes) to look into");
    submission->add_option("--cache", one.cache,
                           "Keep what this grade compiles for the next here: a folder the grader "
                           "alone writes");

    BatchArguments many;
    CLI::App* batch = app.add_subcommand(
        "batch", "Grade a class: every folder and .zip in DIR; resumable; writes grades.csv");
    CLI::Option* class_folder = batch->add_option("folder", many.folder, "The class's submissions")
                                    ->check(CLI::ExistingDirectory);
    batch->add_option("-o,--output", many.output, "Where the reports go (default: grades)");
    batch
        ->add_option("--jobs", many.jobs,
                     "Submissions graded at once; their speed checks run after, one submission at "
                     "a time (default: every core)")
        ->check(CLI::Range(1, 256));
    batch->add_option("--rubric", many.rubric, "The rubric (default: grader/rubric/rubric.json)")
        ->check(CLI::ExistingFile);
    batch->add_flag("--no-speed", many.no_speed, "Leave out the speed checks");
    batch->add_option("--eye-seed", many.eye_seed,
                      "The seed of the eyes the render checks look from, the same for every "
                      "submission (default: drawn anew for the batch)");
    batch
        ->add_option("--shard", many.shard,
                     "Grade only the I-th of N slices of the class, I/N (docs/instructor.md, "
                     "\"Grading a class on several machines\")")
        ->check(
            [](const std::string& text) {
                try {
                    parse_shard(text);
                    return std::string();
                } catch (const std::invalid_argument& error) {
                    return std::string(error.what());
                }
            },
            "I/N");
    CLI::Option* merge =
        batch
            ->add_option("--merge", many.merge,
                         "Write one grades.csv into -o from the output folders of every shard")
            ->check(CLI::ExistingDirectory)
            ->excludes(class_folder);
    batch->callback([class_folder, merge] {
        if (class_folder->count() == 0 && merge->count() == 0) {
            throw CLI::ValidationError(
                "batch needs the class's folder, or --merge and the shards' folders");
        }
    });

    std::string release_folder;
    CLI::App* release_command = app.add_subcommand(
        "release",
        "Write the student starter repository: no solutions, no grader, reference images");
    release_command->add_option("folder", release_folder, "A new, empty folder")->required();

    std::string grading_folder;
    CLI::App* public_cases_command = app.add_subcommand(
        "public-cases",
        "Write a release's grading/ folder alone: the public case files and the rubric");
    public_cases_command->add_option("folder", grading_folder, "Where they go")->required();

    std::string sweep_probe;
    std::string sweep_prefix = "stage8.statistics.";
    std::uint64_t sweep_first = 1;
    int sweep_count = 100;
    CLI::App* seeds_command = app.add_subcommand(
        "seeds", "Run the seeded checks on one built probe at many seeds: how often each fails");
    seeds_command
        ->add_option("probe", sweep_probe,
                     "A probe raystep-grade built (submission --keep-work): WORK/probes/...")
        ->required()
        ->check(CLI::ExistingFile);
    seeds_command->add_option("--checks", sweep_prefix,
                              "The checks whose id starts with this (default: stage8.statistics.)");
    seeds_command->add_option("--first", sweep_first, "The first seed (default: 1)");
    seeds_command->add_option("--count", sweep_count, "How many seeds (default: 100)")
        ->check(CLI::Range(1, 1000000));

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? 0 : 2;
    }
    try {
        if (submission->parsed()) return grade_one(one);
        if (batch->parsed()) return grade_many(many);
        if (release_command->parsed()) return release(release_folder);
        if (seeds_command->parsed()) {
            std::fputs(seed_sweep_text(sweep_seeds(fs::absolute(sweep_probe),
                                                   this_build_toolchain().source, sweep_prefix,
                                                   sweep_first, sweep_count))
                           .c_str(),
                       stdout);
            return 0;
        }
        if (public_cases_command->parsed()) {
            const std::size_t written = write_release_grading(this_build_toolchain().source,
                                                              built_rubric(), grading_folder);
            std::printf("wrote %zu public case files and the rubric to %s\n", written,
                        grading_folder.c_str());
            return 0;
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "raystep-grade: %s\n", error.what());
        return 1;
    }
    return 1;
}
