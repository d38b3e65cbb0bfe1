#include "grader/grade/batch.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>

#include "grader/grade/check_definition.h"
#include "grader/grade/merge_shards.h"
#include "grader/grade/report_folders.h"
#include "grader/grade/report_json.h"
#include "grader/grade/speed_pass.h"
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
    for (int stage = 1; stage <= kLastStage; ++stage)
        csv += ",stage" + std::to_string(stage);
    csv += ",pipeline,checks_passed,checks,seconds\r\n";
    for (const GradeReport& r : reports) {
        const std::vector<std::pair<double, double>> stages = r.stage_scores();
        const std::size_t passed = static_cast<std::size_t>(
            std::count_if(r.checks.begin(), r.checks.end(),
                          [](const CheckResult& c) { return c.outcome == Outcome::passed; }));
        csv += csv_field(r.student) + "," + number(r.score()) + "," + number(r.max_score());
        for (int stage = 1; stage <= kLastStage; ++stage) {
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

    // What each submission still needs: a report finished before (resumed) may lack only the
    // speed checks, when a batch stopped between its passes.
    std::vector<std::optional<GradeReport>> reports(mine.size());
    std::vector<bool> failed(mine.size(), false);
    std::vector<bool> resumed(mine.size(), false);
    for (std::size_t k = 0; k < mine.size(); ++k) {
        reports[k] = finished_report(options.output / mine[k].name);
        resumed[k] =
            reports[k].has_value() && (options.skip_speed || !lacks_speed_checks(*reports[k]));
    }
    // What the class's grades keep for one another (GradeOptions::cache): a stage nobody has
    // started is compiled once, the speed pass compiles nothing new, and the reference's noisy
    // renders are made once. In OUT, where no student's folder can be called so
    // (submission_name), and removed when the batch ends.
    const fs::path cache = options.output / ".cache";
    // One eye for the class's render checks (checks/moved_eye.h), drawn as the batch starts: no
    // submission can know it beforehand, nor tell another while the batch runs, since each is
    // sandboxed; and the reference's noisy renders from it are made once for the class. A batch
    // resumed later draws another.
    const std::uint64_t eye_seed = options.eye_seed.value_or(fresh_grade_seed());
    std::mutex mutex;  // the tally's stderr lines and the progress line
    std::size_t done = 0;
    const auto progress = [&](const char* pass, std::size_t total, const std::string& name) {
        if (!options.progress) return;
        const std::lock_guard<std::mutex> lock(mutex);
        std::fprintf(stderr, "\r\033[K%s [%zu/%zu] %s", pass, ++done, total, name.c_str());
    };
    const auto grade = [&](std::size_t k, bool speed) {
        const ClassEntry& entry = mine[k];
        GradeOptions one;
        one.submission = entry.submission;
        one.output = options.output / entry.name;
        // The first pass shares the cores among submissions; the second has them all to build
        // with, and times its checks alone whatever `jobs` is (grade_submission.h).
        one.jobs = speed ? options.jobs : 1;
        one.skip_speed = !speed;
        one.only_speed = speed;
        one.reference_probe = options.reference_probe;
        one.cache = cache;
        one.eye_seed = eye_seed;
        one.reproduce = "raystep-grade submission " + entry.submission.string();
        try {
            GradeReport report = grade_submission(one, rubric, toolchain);
            report.student = entry.name;
            if (speed) report = with_speed_checks(std::move(*reports[k]), report);
            write_reports(report, one.output);
            reports[k] = std::move(report);
        } catch (const std::exception& error) {
            const std::lock_guard<std::mutex> lock(mutex);
            std::fprintf(stderr, "\nraystep-grade: %s: %s\n", entry.submission.string().c_str(),
                         error.what());
            failed[k] = true;
            reports[k].reset();
        }
    };

    // Pass 1: every check but speed, `jobs` submissions at a time, each with one compile or check
    // at a time.
    std::vector<std::size_t> first_pass;
    for (std::size_t k = 0; k < mine.size(); ++k) {
        if (!reports[k]) first_pass.push_back(k);
    }
    std::atomic<std::size_t> next{0};
    std::vector<std::thread> workers;
    for (int w = 0; w < std::max(1, options.jobs); ++w) {
        workers.emplace_back([&] {
            for (std::size_t i = next++; i < first_pass.size(); i = next++) {
                progress("checks", first_pass.size(), mine[first_pass[i]].name);
                grade(first_pass[i], false);
            }
        });
    }
    for (std::thread& worker : workers)
        worker.join();

    // Pass 2: the speed checks, one submission at a time, nothing else running, so that every
    // submission's timings are taken alike on an otherwise idle machine.
    if (!options.skip_speed) {
        std::vector<std::size_t> second_pass;
        for (std::size_t k = 0; k < mine.size(); ++k) {
            if (reports[k] && lacks_speed_checks(*reports[k])) second_pass.push_back(k);
        }
        done = 0;
        for (const std::size_t k : second_pass) {
            progress("speed", second_pass.size(), mine[k].name);
            grade(k, true);
        }
    }
    if (options.progress) std::fputs("\r\033[K", stderr);
    std::error_code ignored;
    fs::remove_all(cache, ignored);

    BatchTally tally;
    std::vector<GradeReport> class_reports;
    for (std::size_t k = 0; k < mine.size(); ++k) {
        if (failed[k]) {
            ++tally.failed;
            continue;
        }
        ++(resumed[k] ? tally.resumed : tally.graded);
        class_reports.push_back(std::move(*reports[k]));
    }
    write_grades_csv(class_reports, options.output);
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
