#pragma once

#include <filesystem>

#include "grader/report/grade_report.h"

namespace raystep::grade {

/// Writes every report of `report` into `folder`: results.json (Gradescope), prairielearn.json,
/// junit.xml, index.html (the student's view), instructor.html (every check) and, last,
/// report.json (the whole report, which a resumed batch takes as the mark of a finished one).
void write_reports(const GradeReport& report, const std::filesystem::path& folder);

}  // namespace raystep::grade
