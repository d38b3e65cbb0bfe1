#include "grader/grade/merge_shards.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

#include "grader/grade/report_json.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

ShardRecord read_shard_record(const fs::path& folder) {
    const fs::path file = shard_record_file(folder);
    std::ifstream in(file);
    if (!in) {
        throw std::runtime_error(folder.string() +
                                 " is not a shard's output: it has no shard.json, which "
                                 "`raystep-grade batch --shard I/N` writes");
    }
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        ShardRecord record;
        record.index = j.at("shard").get<int>();
        record.count = j.at("of").get<int>();
        record.class_size = j.at("class_size").get<std::size_t>();
        record.students = j.at("students").get<std::vector<std::string>>();
        return record;
    } catch (const std::exception& error) {
        throw std::runtime_error(file.string() + ": " + error.what());
    }
}

// What a report was graded with: each check and what it was worth.
std::vector<std::pair<std::string, double>> checks_and_points(const GradeReport& report) {
    std::vector<std::pair<std::string, double>> signature;
    for (const CheckResult& check : report.checks)
        signature.emplace_back(check.id, check.max_score);
    std::sort(signature.begin(), signature.end());
    return signature;
}

// The first check where two signatures part, for the warning.
std::string first_difference(const std::vector<std::pair<std::string, double>>& a,
                             const std::vector<std::pair<std::string, double>>& b) {
    const auto [in_a, in_b] = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
    const auto& where = in_a != a.end() ? *in_a : *in_b;
    return where.first;
}

}  // namespace

fs::path shard_record_file(const fs::path& output) {
    return output / "shard.json";
}

void write_shard_record(const ShardRecord& record, const fs::path& output) {
    const nlohmann::json j = {{"shard", record.index},
                              {"of", record.count},
                              {"class_size", record.class_size},
                              {"students", record.students}};
    std::ofstream out(shard_record_file(output));
    out << j.dump(2) << "\n";
    out.close();
    if (!out) throw std::runtime_error(shard_record_file(output).string() + ": cannot be written");
}

MergedClass merge_shards(const std::vector<fs::path>& shard_folders) {
    MergedClass merged;
    std::map<int, fs::path> seen;  // shard index -> its folder
    std::optional<ShardRecord> first;
    fs::path first_folder;
    std::vector<std::pair<std::string, double>> baseline;
    std::string baseline_student;
    for (const fs::path& folder : shard_folders) {
        const ShardRecord record = read_shard_record(folder);
        const std::string name = folder.string() + " (shard " + std::to_string(record.index) + "/" +
                                 std::to_string(record.count) + ")";
        if (!first) {
            first = record;
            first_folder = folder;
        } else if (record.count != first->count || record.class_size != first->class_size) {
            merged.warnings.push_back(
                name + " is a shard of " + std::to_string(record.count) + " of a class of " +
                std::to_string(record.class_size) + ", but " + first_folder.string() +
                " is one of " + std::to_string(first->count) + " of a class of " +
                std::to_string(first->class_size) + ": are they the same class?");
        }
        if (const auto [where, added] = seen.emplace(record.index, folder); !added) {
            merged.warnings.push_back(name + " is given twice, also as " + where->second.string() +
                                      "; its students are counted once");
            continue;
        }
        for (const std::string& student : record.students) {
            std::optional<GradeReport> report = finished_report(folder / student);
            if (!report) {
                merged.warnings.push_back(
                    (folder / student).string() +
                    " has no finished report: the shard's run stopped; run it again, it resumes");
                continue;
            }
            const auto signature = checks_and_points(*report);
            if (baseline_student.empty()) {
                baseline = signature;
                baseline_student = student;
            } else if (signature != baseline) {
                merged.warnings.push_back(
                    student + " in " + name + " was graded with other checks or points than " +
                    baseline_student + " (first at " + first_difference(signature, baseline) +
                    "): merge shards graded by one grader, rubric and options (--no-speed)");
            }
            merged.reports.push_back(std::move(*report));
        }
    }
    if (first) {
        for (int index = 1; index <= first->count; ++index) {
            if (seen.count(index) == 0) {
                merged.warnings.push_back("shard " + std::to_string(index) + "/" +
                                          std::to_string(first->count) +
                                          " is missing: its students are not in grades.csv");
            }
        }
    }
    std::sort(merged.reports.begin(), merged.reports.end(),
              [](const GradeReport& a, const GradeReport& b) { return a.student < b.student; });
    return merged;
}

}  // namespace raystep::grade
