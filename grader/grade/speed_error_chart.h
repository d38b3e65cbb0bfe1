#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/report/grade_report.h"

namespace raystep::grade {

/// The report's speed-against-error chart, as the data scripts/draw-charts.py draws ("study":
/// "pareto-family"): the reference's points for the family of stage3.speed.intersect_triangle,
/// from the JSON `raystep-reference bench --pareto` wrote (`reference_json`), with the submission's
/// intersect_triangle added as a point of its own precision, "submission", which the script draws
/// as a labelled diamond. Its speed is its measured ratio to the reference's Cramer times the
/// chart's own Cramer point, so that it lands on the chart's scale whatever machine graded it.
/// nullopt when the report has no such measurement, or the JSON is missing or lacks the family.
std::optional<nlohmann::json> speed_error_chart_data(const GradeReport& report,
                                                     const std::filesystem::path& reference_json);

/// The chart as one inline <svg> element, drawn by scripts/draw-charts.py with the Python that
/// has matplotlib (built_chart_python(), chosen when CMake configured). Empty where there is no
/// such Python, or the script fails or takes longer than a minute: the HTML then shows no chart.
std::string draw_chart_svg(const nlohmann::json& data);

}  // namespace raystep::grade
