#include "grader/grade/grade_submission.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <mutex>
#include <thread>

#include "grader/grade/check_definition.h"
#include "grader/grade/probe_builder.h"
#include "grader/grade/report_json.h"
#include "grader/grade/speed_error_chart.h"
#include "grader/grade/stage_manifests.h"
#include "grader/grade/submission.h"
#include "grader/report/gradescope_results.h"
#include "grader/report/html_report.h"
#include "grader/report/junit_xml.h"
#include "grader/report/prairielearn_results.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

CheckResult score(const CheckDefinition& check, const CheckMeasure& measure, const Rubric& rubric) {
    const RubricEntry& entry = rubric.entry(check.id);
    CheckResult result;
    result.id = check.id;
    result.stage = check.stage;
    result.kind = check.kind;
    result.name = check.name;
    result.outcome = measure.outcome;
    result.max_score = entry.points;
    result.visibility = entry.visibility;
    // A stage that did not compile or is still a stub earns nothing; one that crashed or ran out
    // of time partway keeps the cases it answered right.
    const bool scorable = measure.outcome != Outcome::did_not_compile &&
                          measure.outcome != Outcome::not_implemented;
    result.score = scorable ? entry.score(measure.fraction) : 0.0;
    result.summary = measure.summary;
    result.counterexamples = measure.counterexamples;
    result.metrics = measure.metrics;
    result.images = measure.images;
    result.details = measure.details;
    return result;
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
    const Submission submission =
        take_submission(options.submission, read_stage_manifests(toolchain.source), work, toolchain);
    report.student = submission.name;
    report.times.intake = seconds_since(start);

    start = std::chrono::steady_clock::now();
    const ProbeSet probes = build_probes(submission, toolchain, work, options.jobs);
    report.times.build = seconds_since(start);

    start = std::chrono::steady_clock::now();
    GradingContext context;
    context.probes = &probes;
    context.source = toolchain.source;
    context.report_folder = options.output;
    context.reference_probe = options.reference_probe;
    context.reproduce = options.reproduce;
    context.only_case = options.only_case;

    std::vector<CheckDefinition> checks = all_checks();
    if (!options.only_check.empty()) {
        checks.erase(std::remove_if(checks.begin(), checks.end(),
                                    [&](const CheckDefinition& c) { return c.id != options.only_check; }),
                     checks.end());
        if (checks.empty()) throw std::invalid_argument("no check " + options.only_check);
    }
    if (options.only_stage) {
        checks.erase(std::remove_if(checks.begin(), checks.end(),
                                    [&](const CheckDefinition& c) { return c.stage != *options.only_stage; }),
                     checks.end());
        if (checks.empty()) throw std::invalid_argument("no checks for stage " + std::to_string(*options.only_stage));
    }
    if (options.skip_speed) {
        checks.erase(std::remove_if(checks.begin(), checks.end(),
                                    [](const CheckDefinition& c) { return c.kind == "speed"; }),
                     checks.end());
    }
    for (const CheckDefinition& check : checks) rubric.entry(check.id);  // every check is scored

    // Checks run `jobs` at a time: each talks to its own probe process. Speed checks run alone
    // afterwards, so that nothing else competes for the processors while they time.
    std::vector<CheckResult> results(checks.size());
    const auto run = [&](std::size_t k) {
        const CheckDefinition& check = checks[k];
        const BuiltProbe& probe = check.stage == 0 ? probes.pipeline : probes.stage(check.stage);
        results[k] = score(check, check.measure(context, probe), rubric);
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
    for (std::thread& worker : workers) worker.join();
    for (std::size_t k = 0; k < checks.size(); ++k) {
        if (checks[k].kind == "speed") run(k);
    }
    report.checks = std::move(results);
    report.times.checks = seconds_since(start);
    return report;
}

void write_reports(const GradeReport& report, const fs::path& folder) {
    fs::create_directories(folder);
    const auto write = [&](const char* name, const std::string& text) {
        std::ofstream out(folder / name);
        out << text;
        if (!out) throw std::runtime_error((folder / name).string() + ": cannot be written");
    };
    write("results.json", gradescope_results(report).dump(2) + "\n");
    write("prairielearn.json", prairielearn_results(report).dump(2) + "\n");
    write("junit.xml", junit_xml(report, Audience::instructor));
    HtmlReportOptions student;
    student.speed_error_chart_svg = speed_error_chart_svg(report, RAYSTEP_PARETO_REFERENCE);
    write_html_report(report, folder, student);
    HtmlReportOptions instructor = student;
    instructor.audience = Audience::instructor;
    write("instructor.html", html_report(report, folder, instructor));
    // Last: a complete report.json is how a resumed batch knows this submission is done.
    write("report.json", report_json(report).dump(2) + "\n");
}

}  // namespace raystep::grade
