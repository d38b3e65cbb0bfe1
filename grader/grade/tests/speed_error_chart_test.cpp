// The report's speed-against-error chart: the submission's point on the reference's chart.

#include "grader/grade/speed_error_chart.h"

#include <filesystem>
#include <fstream>
#include <optional>

#include <nlohmann/json.hpp>

#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"
#include "grader/grade/checks/stage_checks.h"
#include "studies/speed_error/pareto_json.h"

using namespace raystep;
using namespace raystep::grade;

namespace {

// The reference's JSON with one family: Cramer at 20 Mrays/s.
std::filesystem::path write_reference(const raystep::testing::ScratchFolder& folder,
                                      const std::string& family_name) {
    ParetoFamily family;
    family.name = family_name;
    family.description = "rays through shared edges";
    family.cases = 100;
    ParetoPoint cramer;
    cramer.label = "Cramer";
    cramer.precision = "double";
    cramer.function = "intersect_triangle_cramer";
    cramer.cases = 100;
    cramer.mrays_per_second = 20.0;
    family.points = {cramer};
    const std::filesystem::path path = folder.path() / (family_name + ".json");
    std::ofstream(path) << pareto_json("machine", "2026-11-21", {family}, {}).dump();
    return path;
}

GradeReport report_with_measurement(Outcome outcome) {
    CheckResult check;
    check.id = kSpeedErrorCheck;
    check.outcome = outcome;
    check.metrics = {{kSpeedErrorCases, 2000},      {kSpeedErrorFalseHits, 0},
                     {kSpeedErrorFalseMisses, 200}, {kSpeedErrorUlpsMedian, 1},
                     {kSpeedErrorUlpsP99, 20},      {kSpeedErrorAgainstCramer, 0.5}};
    GradeReport report;
    report.checks = {check};
    return report;
}

}  // namespace

TEST_CASE("speed_error_chart_data: the submission is a point of its own at its speed ratio",
          "[report]") {
    const raystep::testing::ScratchFolder scratch("speed-error-chart-test");
    const std::optional<nlohmann::json> data = speed_error_chart_data(
        report_with_measurement(Outcome::passed), write_reference(scratch, "shared-edges"));
    REQUIRE(data);
    CHECK(data->at("study") == "pareto-family");
    CHECK(data->at("footnote").get<std::string>().find("Diamond: yours on 2000 cases") !=
          std::string::npos);
    const nlohmann::json& points = data->at("family").at("points");
    REQUIRE(points.size() == 2);
    const nlohmann::json& yours = points.at(1);
    CHECK(yours.at("label") == "your intersect_triangle");
    CHECK(yours.at("precision") == "submission");
    CHECK(yours.at("mrays_per_second") == 10.0);  // half of Cramer's 20 Mrays/s
    CHECK(yours.at("wrong_share") == 0.1);        // 200 false misses of 2000 cases
    CHECK(yours.at("t_ulps").at("p99") == 20.0);
}

TEST_CASE("speed_error_chart_data: none without a measurement or a reference", "[report]") {
    const raystep::testing::ScratchFolder scratch("speed-error-chart-test");
    const std::filesystem::path reference = write_reference(scratch, "shared-edges");
    CHECK(!speed_error_chart_data(report_with_measurement(Outcome::not_implemented), reference));
    CHECK(!speed_error_chart_data(GradeReport{}, reference));
    CHECK(!speed_error_chart_data(report_with_measurement(Outcome::passed),
                                  reference.string() + ".missing"));
    CHECK(!speed_error_chart_data(report_with_measurement(Outcome::passed),
                                  write_reference(scratch, "slivers")));
}

// scripts/draw-charts.py draws it where CMake found a Python with matplotlib; else no chart.
TEST_CASE("draw_chart_svg: one inline <svg> element with the submission labelled", "[report]") {
    const raystep::testing::ScratchFolder scratch("speed-error-chart-test");
    const std::optional<nlohmann::json> data = speed_error_chart_data(
        report_with_measurement(Outcome::passed), write_reference(scratch, "shared-edges"));
    REQUIRE(data);
    const std::string svg = draw_chart_svg(*data);
    if (std::string(RAYSTEP_CHART_PYTHON).empty()) {
        CHECK(svg.empty());
        return;
    }
    CHECK(svg.rfind("<svg ", 0) == 0);
    CHECK(svg.size() - svg.rfind("</svg>") == 6);
    CHECK(svg.find("<?xml") == std::string::npos);
    CHECK(svg.find("<!DOCTYPE") == std::string::npos);
    CHECK(svg.find(">your intersect_triangle</text>") != std::string::npos);
    CHECK(svg.find("Diamond: yours on 2000 cases") != std::string::npos);
}

TEST_CASE("draw_chart_svg: no chart from data the script cannot draw", "[report]") {
    CHECK(draw_chart_svg(nlohmann::json{{"study", "pareto-family"}}).empty());
}
