// raystep grade's stage-3 checks over the public case files
// (grading/3_intersect/case_file_judges.h).

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "base/testing/catch.h"

#include "app/check/case_file.h"
#include "app/check/stage3_methods.h"
#include "grading/3_intersect/case_file_judges.h"

namespace raystep::grade {
namespace {

// Each function's check worth one point, full at the reference's count, nothing at 70% of it.
Rubric one_point_each() {
    Rubric rubric;
    for (const Stage3Method& method : stage3_methods())
        rubric.checks["stage3.cases." + method.name] = {1.0, 1.0, 0.7, Visibility::visible};
    return rubric;
}

// Public case files by name (stages/3_intersect/cases/NAME.cases).
std::vector<CaseFamily> case_files(const std::vector<std::string>& names) {
    std::vector<CaseFamily> families;
    for (const std::string& name : names) {
        for (CaseFamily& family : read_case_file(std::string(RAYSTEP_SOURCE_DIR) +
                                                 "/stages/3_intersect/cases/" + name + ".cases"))
            families.push_back(std::move(family));
    }
    return families;
}

// A copy: the results are often a temporary.
CheckResult check_of(const std::vector<CheckResult>& results, const std::string& method) {
    const auto found = std::find_if(results.begin(), results.end(), [&](const CheckResult& r) {
        return r.id == "stage3.cases." + method;
    });
    REQUIRE(found != results.end());
    return *found;
}

TEST_CASE("the stage-3 fraction is the count right over the reference's, at most 1") {
    CHECK(stage3_cases_fraction(90, 90) == 1.0);
    CHECK(stage3_cases_fraction(95, 90) == 1.0);
    CHECK(stage3_cases_fraction(45, 90) == 0.5);
    CHECK(stage3_cases_fraction(0, 0) == 1.0);
}

TEST_CASE("each stage-3 function earns its own points, whatever the others do") {
    // The reference's counts, with the sphere's raised past what it gets: the sphere loses points
    // in proportion and fails, and every other function keeps its full point.
    const std::vector<CaseFamily> families = case_files({"shared-edges", "random-spheres"});
    std::map<std::string, std::size_t> counts = stage3_cases_right(families);
    REQUIRE(counts.at("intersect_sphere") > 0);
    counts["intersect_sphere"] *= 2;
    const std::vector<CheckResult> results =
        run_stage3_case_checks(families, counts, one_point_each());
    CHECK(results.size() == stage3_methods().size());
    const CheckResult sphere = check_of(results, "intersect_sphere");
    CHECK(sphere.outcome == Outcome::failed);
    CHECK(sphere.score == 0.0);  // half the reference's count: below 0.7
    const CheckResult plane = check_of(results, "intersect_plane");
    CHECK(plane.outcome == Outcome::passed);
    CHECK(plane.score == 1.0);
    CHECK(plane.max_score == 1.0);
}

TEST_CASE("a stage-3 function short of the reference's count keeps points in proportion") {
    const std::vector<CaseFamily> families = case_files({"shared-edges"});
    std::map<std::string, std::size_t> counts = stage3_cases_right(families);
    const std::size_t right = counts.at("intersect_triangle");
    REQUIRE(right > 20);
    // 85% of the reference's count, halfway between 0.7 and 1: half the point.
    counts["intersect_triangle"] = static_cast<std::size_t>(static_cast<double>(right) / 0.85);
    const CheckResult triangle =
        check_of(run_stage3_case_checks(families, counts, one_point_each()), "intersect_triangle");
    CHECK(triangle.outcome == Outcome::failed);
    CHECK(std::abs(triangle.score - 0.5) < 0.05);
}

TEST_CASE("intersect_triangle is held to the lowest count of the three triangle methods") {
    // A student may hand in any of the three lecture methods as intersect_triangle, and the
    // reference's projection and half-space tests miss near-boundary cases its watertight test
    // gets right: a student's projection must still earn full marks there.
    const std::map<std::string, std::size_t> counts =
        stage3_cases_right(case_files({"shared-edges", "slivers", "grazing"}));
    const std::size_t lowest = std::min({counts.at("intersect_triangle_projection"),
                                         counts.at("intersect_triangle_halfspaces"),
                                         counts.at("intersect_triangle_cramer")});
    CHECK(counts.at("intersect_triangle") == lowest);
}

TEST_CASE("a lecture triangle test that only leaks at shared edges passes raystep grade's check") {
    // The reference's Cramer leaks at shared edges and gets every other case there right. Held to
    // a watertight test's count, every case, it must still pass: a leak counts as right, as the
    // grader counts it, or a right stage 3 loses points.
    const std::vector<CaseFamily> families = case_files({"shared-edges"});
    std::map<std::string, std::size_t> watertight = stage3_cases_right(families);
    const double cases = check_of(run_stage3_case_checks(families, watertight, one_point_each()),
                                  "intersect_triangle_cramer")
                             .metrics.at("cases");
    watertight["intersect_triangle_cramer"] = static_cast<std::size_t>(cases);
    const CheckResult cramer =
        check_of(run_stage3_case_checks(families, watertight, one_point_each()),
                 "intersect_triangle_cramer");
    INFO(cramer.summary);
    CHECK(cramer.outcome == Outcome::passed);
    CHECK(cramer.score == 1.0);
    CHECK_THAT(cramer.summary, Catch::Matchers::Contains("leaks at shared edges"));
    CHECK(cramer.counterexamples.empty());
}

}  // namespace
}  // namespace raystep::grade
