#pragma once

#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/report/grade_report.h"

namespace raystep::grade {

/// The whole report as JSON (report.json beside the other reports): every check with every field,
/// and the phase times. `raystep-grade batch` reads it back to resume and to write the class CSV.
nlohmann::json report_json(const GradeReport& report);

/// Throws (nlohmann's json::exception, or std::invalid_argument) for anything that is not what
/// report_json writes: a half-written file from an interrupted run is graded again.
GradeReport report_from_json(const nlohmann::json& j);

/// The report a run wrote completely into `output` (its finished_report_file, report_folders.h),
/// or nothing: no file, or one an interrupted run left half-written.
std::optional<GradeReport> finished_report(const std::filesystem::path& output);

}  // namespace raystep::grade
