// The report's speed-against-error chart: the submission's point on the reference's chart.

#include "grader/grade/speed_error_chart.h"

#include <filesystem>
#include <fstream>

#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"
#include "grader/grade/checks/stage_checks.h"
#include "studies/speed_error/pareto_json.h"

using namespace raystep;
using namespace raystep::grade;

namespace {

// The reference's JSON with one family: Cramer at 20 Mrays/s.
std::filesystem::path write_reference(const testing::ScratchFolder& folder,
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

TEST_CASE("speed_error_chart_svg: the submission is a labelled diamond at its speed ratio",
          "[report]") {
    const testing::ScratchFolder scratch("speed-error-chart-test");
    const std::string svg = speed_error_chart_svg(report_with_measurement(Outcome::passed),
                                                  write_reference(scratch, "shared-edges"));
    REQUIRE(!svg.empty());
    CHECK(svg.find(">your intersect_triangle</text>") != std::string::npos);
    CHECK(svg.find("Diamond: yours on 2000 cases") != std::string::npos);
    // Half of Cramer's 20 Mrays/s: the x axis ends at 1.1 times the fastest point (22), so the
    // diamond sits at 10/22 of the 300-unit-wide panel that starts at x = 70.
    CHECK(svg.find("<path d=\"M206.4,") != std::string::npos);
}

TEST_CASE("speed_error_chart_svg: no chart without a measurement or a reference", "[report]") {
    const testing::ScratchFolder scratch("speed-error-chart-test");
    const std::filesystem::path reference = write_reference(scratch, "shared-edges");
    CHECK(speed_error_chart_svg(report_with_measurement(Outcome::not_implemented), reference)
              .empty());
    CHECK(speed_error_chart_svg(GradeReport{}, reference).empty());
    CHECK(speed_error_chart_svg(report_with_measurement(Outcome::passed),
                                reference.string() + ".missing")
              .empty());
    CHECK(speed_error_chart_svg(report_with_measurement(Outcome::passed),
                                write_reference(scratch, "slivers"))
              .empty());
}
