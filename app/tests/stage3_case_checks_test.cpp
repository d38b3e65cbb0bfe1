// raystep grade's stage-3 checks over the public case files (app/grade/stage3_case_checks.h).

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "app/check/case_file.h"
#include "app/grade/stage3_case_checks.h"

namespace raystep::grade {
namespace {

TEST_CASE("a lecture triangle test that only leaks at shared edges passes raystep grade's check") {
    // The reference's Cramer leaks at shared edges, where its watertight intersect_triangle
    // leaks nowhere. A student's Cramer is held to the watertight count (a student may hand in
    // Cramer as intersect_triangle): a leak must count as right, as the grader counts it, or a
    // right stage 3 fails.
    const std::vector<CaseFamily> families = read_case_file(
        std::string(RAYSTEP_SOURCE_DIR) + "/stages/3_intersect/cases/shared-edges.cases");
    const std::map<std::string, std::size_t> counts = stage3_cases_right(families);
    std::map<std::string, std::size_t> watertight = counts;
    watertight["intersect_triangle_cramer"] = counts.at("intersect_triangle");
    const std::vector<CheckResult> results = run_stage3_case_checks(families, watertight);
    const auto cramer = std::find_if(results.begin(), results.end(), [](const CheckResult& result) {
        return result.id == "stage3.cases.intersect_triangle_cramer";
    });
    REQUIRE(cramer != results.end());
    INFO(cramer->summary);
    CHECK(cramer->outcome == Outcome::passed);
    CHECK_THAT(cramer->summary, Catch::Matchers::Contains("leaks at shared edges"));
    CHECK(cramer->counterexamples.empty());
}

}  // namespace
}  // namespace raystep::grade
