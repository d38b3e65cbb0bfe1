#include "grader/grade/grade_submission.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "grader/grade/check_definition.h"
#include "grader/grade/check_score.h"
#include "grader/grade/probe_builder.h"
#include "grader/grade/report_folders.h"
#include "grader/grade/stage_manifests.h"
#include "grader/grade/submission.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

GradeReport grade_submission(const GradeOptions& options, const Rubric& rubric,
                             const ProbeToolchain& toolchain) {
    GradeReport report;
    report.submission = options.submission.string();
    const fs::path work = options.output / "work";
    fs::remove_all(work);
    fs::create_directories(work);

    auto start = std::chrono::steady_clock::now();
    const Submission submission = take_submission(
        options.submission, read_stage_manifests(toolchain.source), work, toolchain);
    report.student = submission.name;
    report.times.intake = seconds_since(start);

    start = std::chrono::steady_clock::now();
    const ProbeSet probes = build_probes(submission, toolchain, work, options.jobs);
    report.times.build = seconds_since(start);

    start = std::chrono::steady_clock::now();
    GradingContext context;
    context.probes = &probes;
    context.source = toolchain.source;
    context.report_folder = instructor_folder(options.output);
    context.reference_probe = options.reference_probe;
    context.reproduce = options.reproduce;
    context.only_case = options.only_case;

    std::vector<CheckDefinition> checks = all_checks();
    if (!options.only_check.empty()) {
        checks.erase(
            std::remove_if(checks.begin(), checks.end(),
                           [&](const CheckDefinition& c) { return c.id != options.only_check; }),
            checks.end());
        if (checks.empty()) throw std::invalid_argument("no check " + options.only_check);
    }
    if (options.only_stage) {
        checks.erase(std::remove_if(
                         checks.begin(), checks.end(),
                         [&](const CheckDefinition& c) { return c.stage != *options.only_stage; }),
                     checks.end());
        if (checks.empty())
            throw std::invalid_argument("no checks for stage " +
                                        std::to_string(*options.only_stage));
    }
    if (options.skip_speed) {
        checks.erase(std::remove_if(checks.begin(), checks.end(),
                                    [](const CheckDefinition& c) { return c.kind == "speed"; }),
                     checks.end());
    }
    for (const CheckDefinition& check : checks)
        rubric.entry(check.id);  // every check is scored

    // Checks run `jobs` at a time: each talks to its own probe process. Speed checks run alone
    // afterwards, so that nothing else competes for the processors while they time.
    std::vector<CheckResult> results(checks.size());
    const auto run = [&](std::size_t k) {
        const CheckDefinition& check = checks[k];
        const BuiltProbe& probe = check.stage == 0 ? probes.pipeline : probes.stage(check.stage);
        const auto started = std::chrono::steady_clock::now();
        results[k] = score_check(check, check.measure(context, probe), rubric);
        results[k].seconds = seconds_since(started);
    };
    std::atomic<std::size_t> next{0};
    std::vector<std::thread> workers;
    for (int w = 0; w < std::max(1, options.jobs); ++w) {
        workers.emplace_back([&] {
            for (std::size_t k = next++; k < checks.size(); k = next++) {
                if (checks[k].kind != "speed") run(k);
            }
        });
    }
    for (std::thread& worker : workers)
        worker.join();
    for (std::size_t k = 0; k < checks.size(); ++k) {
        if (checks[k].kind == "speed") run(k);
    }
    report.checks = std::move(results);
    report.times.checks = seconds_since(start);
    return report;
}

}  // namespace raystep::grade
