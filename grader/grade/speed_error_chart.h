#pragma once

#include <filesystem>
#include <string>

#include "app/report/grade_report.h"

namespace raystep::grade {

/// The report's speed-against-error chart: the reference's points for the family of
/// stage3.speed.intersect_triangle, from the JSON `raystep-reference bench --pareto` wrote
/// (`pareto_json`), with the submission's intersect_triangle added as a labelled diamond. Its
/// speed is its measured ratio to the reference's Cramer times the chart's own Cramer point, so
/// that it lands on the chart's scale whatever machine graded it. Empty when the report has no
/// such measurement, or the JSON is missing or lacks the family; the HTML then shows no chart.
std::string speed_error_chart_svg(const GradeReport& report,
                                  const std::filesystem::path& pareto_json);

}  // namespace raystep::grade
