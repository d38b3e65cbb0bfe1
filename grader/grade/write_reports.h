#pragma once

#include <filesystem>

#include "app/report/grade_report.h"
#include "grader/grade/report_folders.h"

namespace raystep::grade {

/// Writes every report of `report` into the two folders under `output` (report_folders.h),
/// making them as needed, report.json last. The student's folder gets only the student's views,
/// made from the checks a student is shown (audience.h), with the students' reproduce commands;
/// its HTML page carries the render checks' images, read from the instructor's folder. Throws
/// std::runtime_error naming the file or folder that cannot be written.
void write_reports(const GradeReport& report, const std::filesystem::path& output);

}  // namespace raystep::grade
