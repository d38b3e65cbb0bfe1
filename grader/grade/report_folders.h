#pragma once

#include <filesystem>

namespace raystep::grade {

// Where the reports of one grade go, under the output folder OUT given with -o: OUT/student/
// holds only what a student may be given, OUT/instructor/ everything else.
//
//   OUT/student/index.html          the student's HTML page, its images inside it
//   OUT/student/results.json        the student's grade as JSON (student_results.h)
//   OUT/student/junit.xml           JUnit XML without the withheld checks
//   OUT/instructor/instructor.html  every check, its images linked from renders/
//   OUT/instructor/results.json     Gradescope's (it names hidden checks: Gradescope hides them)
//   OUT/instructor/prairielearn.json
//   OUT/instructor/junit.xml        every check
//   OUT/instructor/renders/         the render checks' images, written while grading
//   OUT/instructor/report.json      everything, written last

/// OUT/student/: what may be sent to the student, or published from the student's CI.
std::filesystem::path student_folder(const std::filesystem::path& output);

/// OUT/instructor/: every other report, and the render checks' images
/// (GradingContext::report_folder), which the reports' image paths are relative to.
std::filesystem::path instructor_folder(const std::filesystem::path& output);

/// OUT/instructor/report.json: the whole report, written after every other, so that a resumed
/// batch takes a readable one as the mark of a finished grade.
std::filesystem::path finished_report_file(const std::filesystem::path& output);

}  // namespace raystep::grade
