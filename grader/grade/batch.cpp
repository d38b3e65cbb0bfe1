#include "grader/grade/batch.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>

#include "grader/grade/merge_shards.h"
#include "grader/grade/report_folders.h"
#include "grader/grade/report_json.h"
#include "grader/grade/submission.h"
#include "grader/grade/write_reports.h"
#include "grader/sandbox/sandbox_paths.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

constexpr const char* kClassCsv = "grades.csv";

std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (const char c : text)
        quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", x);
    return text;
}

}  // namespace

std::vector<ClassEntry> class_submissions(const fs::path& folder, const fs::path& skip) {
    const fs::path output = absolute_normal(skip);
    std::vector<fs::path> paths;
    for (const auto& entry : fs::directory_iterator(folder)) {
        const fs::path path = absolute_normal(entry.path());
        if (is_within(output, path)) continue;
        paths.push_back(entry.path());
    }
    std::sort(paths.begin(), paths.end());
    std::vector<ClassEntry> entries;
    // The class's own files in OUT are taken before any student's name.
    std::map<std::string, int> taken = {{kClassCsv, 1},
                                        {shard_record_file("").filename().string(), 1}};
    for (const fs::path& path : paths) {
        const std::string base = submission_name(path);
        const int seen = ++taken[base];
        entries.push_back({path, seen == 1 ? base : base + "-" + std::to_string(seen)});
    }
    return entries;
}

std::string grades_csv(const std::vector<GradeReport>& reports) {
    std::string csv = "student,score,max_score";
    for (int stage = 1; stage <= 7; ++stage)
        csv += ",stage" + std::to_string(stage);
    csv += ",pipeline,checks_passed,checks,seconds\r\n";
    for (const GradeReport& r : reports) {
        const std::vector<std::pair<double, double>> stages = r.stage_scores();
        const std::size_t passed = static_cast<std::size_t>(
            std::count_if(r.checks.begin(), r.checks.end(),
                          [](const CheckResult& c) { return c.outcome == Outcome::passed; }));
        csv += csv_field(r.student) + "," + number(r.score()) + "," + number(r.max_score());
        for (int stage = 1; stage <= 7; ++stage) {
            csv += "," + (static_cast<std::size_t>(stage) < stages.size()
                              ? number(stages[static_cast<std::size_t>(stage)].first)
                              : "0.00");
        }
        csv += "," + number(stages.empty() ? 0.0 : stages[0].first) + "," + std::to_string(passed) +
               "," + std::to_string(r.checks.size()) + "," +
               number(r.times.intake + r.times.build + r.times.checks + r.times.reports) + "\r\n";
    }
    return csv;
}

BatchTally grade_class(const BatchOptions& options, const Rubric& rubric,
                       const ProbeToolchain& toolchain) {
    const std::vector<ClassEntry> submissions = class_submissions(options.folder, options.output);
    std::vector<ClassEntry> mine;
    for (std::size_t k = 0; k < submissions.size(); ++k) {
        if (options.shard.holds(k)) mine.push_back(submissions[k]);
    }
    fs::create_directories(options.output);
    if (options.shard.count > 1) {
        ShardRecord record{options.shard.index, options.shard.count, submissions.size(), {}};
        for (const ClassEntry& entry : mine)
            record.students.push_back(entry.name);
        write_shard_record(record, options.output);
    }
    BatchTally tally;
    std::vector<GradeReport> reports;
    for (std::size_t k = 0; k < mine.size(); ++k) {
        const ClassEntry& entry = mine[k];
        const fs::path folder = options.output / entry.name;
        if (options.progress) {
            std::fprintf(stderr, "\r\033[K[%zu/%zu] %s", k + 1, mine.size(), entry.name.c_str());
        }
        if (std::optional<GradeReport> done = finished_report(folder)) {
            reports.push_back(std::move(*done));
            ++tally.resumed;
            continue;
        }
        try {
            GradeOptions one;
            one.submission = entry.submission;
            one.output = folder;
            one.jobs = options.jobs;
            one.skip_speed = options.skip_speed;
            one.reference_probe = options.reference_probe;
            one.reproduce = "raystep-grade submission " + entry.submission.string();
            GradeReport report = grade_submission(one, rubric, toolchain);
            report.student = entry.name;
            write_reports(report, folder);
            reports.push_back(std::move(report));
            ++tally.graded;
        } catch (const std::exception& error) {
            std::fprintf(stderr, "\nraystep-grade: %s: %s\n", entry.submission.string().c_str(),
                         error.what());
            ++tally.failed;
        }
    }
    if (options.progress) std::fputs("\r\033[K", stderr);
    write_grades_csv(reports, options.output);
    return tally;
}

void write_grades_csv(const std::vector<GradeReport>& reports, const fs::path& output) {
    fs::create_directories(output);
    std::ofstream csv(output / kClassCsv, std::ios::binary);
    csv << grades_csv(reports);
    csv.close();
    if (!csv) throw std::runtime_error((output / kClassCsv).string() + ": cannot be written");
}

}  // namespace raystep::grade
