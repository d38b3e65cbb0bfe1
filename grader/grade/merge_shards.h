#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/report/grade_report.h"

namespace raystep::grade {

/// What a shard's folder says of itself (OUT/shard.json, written by `batch --shard I/N`): which
/// shard, of how large a class, and the students it holds.
struct ShardRecord {
    int index = 1;
    int count = 1;
    std::size_t class_size = 0;
    std::vector<std::string> students;
};

/// The file in a shard's output folder that says which shard it holds.
std::filesystem::path shard_record_file(const std::filesystem::path& output);

/// Writes OUT/shard.json.
void write_shard_record(const ShardRecord& record, const std::filesystem::path& output);

/// The class put back together from the shards' folders: every finished report, in student
/// order, and a warning for each thing that makes the whole less than the class: a shard missing
/// or given twice, shards of different classes, a student without a finished report, or reports
/// graded with other checks or points than the rest (another rubric, grader, or --no-speed).
struct MergedClass {
    std::vector<GradeReport> reports;
    std::vector<std::string> warnings;
};

/// Throws std::runtime_error naming the folder when one is not a shard's output (no readable
/// shard.json).
MergedClass merge_shards(const std::vector<std::filesystem::path>& shard_folders);

}  // namespace raystep::grade
