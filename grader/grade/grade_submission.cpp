#include "grader/grade/grade_submission.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>

#include "grader/grade/check_definition.h"
#include "grader/grade/check_score.h"
#include "grader/grade/probe_builder.h"
#include "grader/grade/report_folders.h"
#include "grader/grade/sandbox_copies.h"
#include "grader/grade/stage_manifests.h"
#include "grader/grade/submission.h"
#include "grader/grade/work_folder.h"
#include "grader/sandbox/sandbox.h"
#include "grader/sandbox/sandbox_paths.h"
#include "grader/sandbox/sandbox_user.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The checks this grade runs: all of them, narrowed by --check, --stage and --no-speed, or to the
// speed checks alone.
std::vector<CheckDefinition> checks_to_run(const GradeOptions& options, const Rubric& rubric) {
    std::vector<CheckDefinition> checks = all_checks();
    const auto keep_only = [&](const auto& keep) {
        checks.erase(std::remove_if(checks.begin(), checks.end(),
                                    [&](const CheckDefinition& c) { return !keep(c); }),
                     checks.end());
    };
    if (!options.only_check.empty()) {
        keep_only([&](const CheckDefinition& c) { return c.id == options.only_check; });
        if (checks.empty()) throw std::invalid_argument("no check " + options.only_check);
    }
    if (options.only_stage) {
        keep_only([&](const CheckDefinition& c) { return c.stage == *options.only_stage; });
        if (checks.empty()) {
            throw std::invalid_argument("no checks for stage " +
                                        std::to_string(*options.only_stage));
        }
    }
    if (options.skip_speed) keep_only([](const CheckDefinition& c) { return c.kind != "speed"; });
    if (options.only_speed) keep_only([](const CheckDefinition& c) { return c.kind == "speed"; });
    for (const CheckDefinition& check : checks)
        rubric.entry(check.id);  // every check is scored
    return checks;
}

ProbesNeeded probes_needed(const std::vector<CheckDefinition>& checks) {
    ProbesNeeded needed;
    for (const CheckDefinition& check : checks) {
        if (check.stage == 0) {
            needed.pipeline = true;
        } else {
            needed.stages.insert(check.stage);
        }
        if (check.kind == "speed") needed.reference = true;
    }
    return needed;
}

// The scenes the render checks load, copied into the work folder: the sandbox's user reads them
// there whatever the permissions of the repository the grader runs from.
fs::path copy_scenes(const fs::path& source, const fs::path& work) {
    const fs::path copy = work / "source";
    fs::create_directories(copy);
    copy_tree_for_sandbox(source / "scenes", copy / "scenes");
    return copy;
}

// Without bubblewrap, only file permissions keep the grader's secrets from a probe, which could
// otherwise run the reference probe, load a reference stage, read solutions/, the rubric or the
// repository's history, and answer with them. Everything a sandboxed program needs is copied into
// the work folder, so the repository and the build may be shut to others whole; grading waits
// until they are.
void require_repository_shut(const GradeOptions& options, const ProbeToolchain& toolchain) {
    if (bubblewrap_available()) return;
    std::vector<fs::path> secrets = {toolchain.source, options.reference_probe.parent_path()};
    for (const auto& [number, library] : toolchain.stage_libraries)
        secrets.push_back(library.parent_path());
    std::sort(secrets.begin(), secrets.end());
    secrets.erase(std::unique(secrets.begin(), secrets.end()), secrets.end());
    const std::vector<fs::path> open = open_to_sandbox_user(secrets);
    if (open.empty()) return;
    std::string list;
    for (const fs::path& path : open)
        list += " " + path.string();
    throw std::runtime_error(
        "bubblewrap cannot make a sandbox here, and a sandboxed program could enter these folders,"
        " which hold the reference solution:" +
        list + "\nShut them to others (chmod o-rwx" + list +
        ", as grader/gradescope/setup.sh does), or grade where bubblewrap works.");
}

}  // namespace

GradeReport grade_submission(const GradeOptions& options, const Rubric& rubric,
                             const ProbeToolchain& toolchain) {
    const fs::path submission_path = absolute_normal(options.submission);
    const fs::path output = absolute_normal(options.output);
    const std::vector<CheckDefinition> checks = checks_to_run(options, rubric);
    require_repository_shut(options, toolchain);
    fs::create_directories(output);
    const WorkFolder work = make_work_folder(output, options.work_parent, options.keep_work);

    GradeReport report;
    report.submission = options.submission.string();
    report.work_folder = work.kept() ? work.path().string() : "";
    auto start = std::chrono::steady_clock::now();
    const Submission submission =
        take_submission(submission_path, read_stage_manifests(toolchain.source), work.path());
    report.student = submission.name;
    report.intake_problem = submission.problem;
    report.times.intake = seconds_since(start);

    start = std::chrono::steady_clock::now();
    const ProbeSet probes = build_probes(
        submission, toolchain, options.reference_probe, work.path(), probes_needed(checks),
        options.jobs, options.cache.empty() ? fs::path() : options.cache / "objects");
    report.times.build = seconds_since(start);

    start = std::chrono::steady_clock::now();
    GradingContext context;
    context.probes = &probes;
    const bool renders = std::any_of(checks.begin(), checks.end(),
                                     [](const CheckDefinition& c) { return c.kind == "render"; });
    if (renders) context.source = copy_scenes(toolchain.source, work.path());
    context.grader_source = toolchain.source;
    context.report_folder = instructor_folder(output);
    context.reference_probe = probes.reference.program.value_or(fs::path());
    context.eye_seed = options.eye_seed.value_or(fresh_grade_seed());
    context.reproduce = options.reproduce;
    context.only_case = options.only_case;
    if (options.eye_seed && !options.cache.empty()) {
        context.kept_renders =
            options.cache / "renders" / ("eye-" + std::to_string(*options.eye_seed));
    }
    context.timed_walk_seed = fresh_grade_seed();

    // Checks run `jobs` at a time: each talks to its own probe process. Speed checks run alone
    // afterwards, so that nothing else competes for the processors while they time.
    // A check throws only for the grader's own problems (the sandbox cannot start a program);
    // the first is carried out of the worker threads and thrown here, not left to end the grader.
    std::vector<CheckResult> results(checks.size());
    std::mutex failure_mutex;
    std::exception_ptr failure;
    const auto run = [&](std::size_t k) {
        const CheckDefinition& check = checks[k];
        const BuiltProbe& probe = check.stage == 0 ? probes.pipeline : probes.stage(check.stage);
        const auto started = std::chrono::steady_clock::now();
        if (started - start > options.checks_time_limit) {
            CheckMeasure late;
            late.outcome = Outcome::timed_out;
            late.summary = "not run: the grade's checks had taken the " +
                           std::to_string(options.checks_time_limit.count()) +
                           " s they are given, waiting on the submission's time limits";
            results[k] = score_check(check, late, rubric);
            return;
        }
        try {
            results[k] = score_check(check, check.measure(context, probe), rubric);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(failure_mutex);
            if (!failure) failure = std::current_exception();
        }
        results[k].seconds = seconds_since(started);
    };
    // The report keeps the grader's order; a check that shares another's measurement starts
    // after all the rest (check_start_order).
    const std::vector<std::size_t> order = check_start_order(checks);
    std::atomic<std::size_t> next{0};
    std::vector<std::thread> workers;
    for (int w = 0; w < std::max(1, options.jobs); ++w) {
        workers.emplace_back([&] {
            for (std::size_t i = next++; i < order.size(); i = next++)
                run(order[i]);
        });
    }
    for (std::thread& worker : workers)
        worker.join();
    for (std::size_t k = 0; k < checks.size(); ++k) {
        if (checks[k].kind == "speed") run(k);
    }
    if (failure) std::rethrow_exception(failure);
    report.checks = std::move(results);
    report.times.checks = seconds_since(start);
    return report;
}

}  // namespace raystep::grade
