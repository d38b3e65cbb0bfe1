#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "grader/grade/grade_submission.h"
#include "grader/grade/shard.h"

namespace raystep::grade {

struct BatchOptions {
    std::filesystem::path folder;  ///< one entry per student: a folder or a .zip
    std::filesystem::path output;  ///< OUT/<student>/ per student, OUT/grades.csv for the class
    int jobs = 1;  ///< submissions graded at once, each with one compile or check at a time
    bool progress = false;    ///< a progress line on stderr
    bool skip_speed = false;  ///< leave the speed checks out (--no-speed)
    Shard shard;              ///< grade only this slice of the class (--shard I/N)
    /// The eyes of every submission's render checks (--eye-seed); unset: drawn for the batch.
    std::optional<std::uint64_t> eye_seed;
    std::filesystem::path reference_probe;
};

/// One student's submission in a class folder, and the folder its reports go to.
struct ClassEntry {
    std::filesystem::path submission;
    std::string name;  ///< submission_name (submission.h), made unique in the class: "-2", "-3"
};

/// The submissions in `folder`, in name order: every entry (folder, archive, or anything else,
/// which then gets a report saying what it is) but `skip`, the batch's own output folder where
/// it lies inside the class folder, and anything that holds it.
std::vector<ClassEntry> class_submissions(const std::filesystem::path& folder,
                                          const std::filesystem::path& skip);

/// Grades every submission of the class in two passes: every check but speed, `jobs` submissions
/// at a time; then, unless skip_speed, the speed checks, one submission at a time with nothing
/// else running, so that timings stay fair (speed_pass.h). Writes each submission's reports to
/// OUT/<name>/ after each pass: a name made safe, so that nothing is written or removed outside
/// OUT whatever a submission is called. Resumable: a submission whose report.json is already
/// complete is not graded again, and one that lacks only its speed checks gets just those, so a
/// batch stopped halfway picks up where it stopped. A submission that breaks the grader itself
/// (which should not happen) is reported on stderr and skipped, and the rest go on. Writes
/// OUT/grades.csv: one row per student with the total and each stage's score. With a shard other
/// than 1/1 it grades only the shard's submissions, and OUT/grades.csv has only theirs;
/// OUT/shard.json says which they are, for `batch --merge` (merge_shards.h). Returns the number of
/// submissions graded now, skipped (already done), and failed.
struct BatchTally {
    std::size_t graded = 0;
    std::size_t resumed = 0;
    std::size_t failed = 0;
};
BatchTally grade_class(const BatchOptions& options, const Rubric& rubric,
                       const ProbeToolchain& toolchain);

/// The class CSV from the students' reports: header and one row each, fields quoted as RFC 4180
/// wants where they hold a comma, a quote or a line break.
std::string grades_csv(const std::vector<GradeReport>& reports);

/// Writes grades_csv(reports) to OUT/grades.csv; throws naming the file when it cannot.
void write_grades_csv(const std::vector<GradeReport>& reports, const std::filesystem::path& output);

}  // namespace raystep::grade
