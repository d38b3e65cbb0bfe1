#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grader/grade/grade_submission.h"

namespace raystep::grade {

struct BatchOptions {
    std::filesystem::path folder;  ///< one entry per student: a folder or a .zip
    std::filesystem::path output;  ///< OUT/<student>/ per student, OUT/grades.csv for the class
    int jobs = 1;
    bool progress = false;  ///< a progress line on stderr
    std::filesystem::path reference_probe;
};

/// The submissions in `folder`, by name: every sub-folder and .zip file, in name order.
std::vector<std::filesystem::path> class_submissions(const std::filesystem::path& folder);

/// Grades every submission of the class, one after another, each with `jobs` compiles and checks
/// at a time, and writes its reports to OUT/<name>/. Resumable: a submission whose report.json
/// is already complete is not graded again, so a batch stopped halfway picks up where it stopped.
/// A submission that breaks the grader itself (which should not happen) is reported on stderr and
/// skipped, and the rest go on. Writes OUT/grades.csv: one row per student with the total and
/// each stage's score. Returns the number of submissions graded now, skipped (already done), and
/// failed.
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

}  // namespace raystep::grade
