#include "app/report/grade_report.h"

#include <stdexcept>

#include "base/testing/catch.h"
#include "report_example.h"

using namespace raystep::grade;
using raystep::testing::example_report;

TEST_CASE("outcome_name and visibility_name: the words the reports print", "[report]") {
    CHECK(outcome_name(Outcome::passed) == "passed");
    CHECK(outcome_name(Outcome::failed) == "failed");
    CHECK(outcome_name(Outcome::crashed) == "crashed");
    CHECK(outcome_name(Outcome::timed_out) == "timed out");
    CHECK(outcome_name(Outcome::not_implemented) == "not implemented");
    CHECK(outcome_name(Outcome::did_not_compile) == "did not compile");
    // Gradescope's own names: gradescope_results passes them through.
    CHECK(visibility_name(Visibility::visible) == "visible");
    CHECK(visibility_name(Visibility::hidden) == "hidden");
    CHECK(visibility_name(Visibility::after_due_date) == "after_due_date");
    CHECK(visibility_name(Visibility::after_published) == "after_published");
    CHECK_THROWS_AS(outcome_name(static_cast<Outcome>(99)), std::invalid_argument);
}

TEST_CASE("GradeReport: the total and the maximum add up every check, hidden ones too",
          "[report]") {
    const GradeReport report = example_report();
    // 2 + 3 + 0 + 1.5 + 0 + 0 (hidden) + 0 + 0 + 3 + 2 + 1 + 4, out of
    // 2 + 3 + 4 + 5 + 2 + 4 (hidden) + 3 + 4 + 3 + 5 + 1 + 4.
    CHECK(report.score() == 16.5);
    CHECK(report.max_score() == 40.0);
    CHECK(GradeReport{}.score() == 0.0);
}

TEST_CASE("GradeReport::stage_scores: one entry per stage, the pipeline at index 0", "[report]") {
    const auto scores = example_report().stage_scores();
    REQUIRE(scores.size() == kLastStage + 1);
    CHECK(scores[0] == std::pair<double, double>(4, 4));
    CHECK(scores[1] == std::pair<double, double>(5, 5));
    CHECK(scores[2] == std::pair<double, double>(0, 4));
    CHECK(scores[3] == std::pair<double, double>(1.5, 11));
    CHECK(scores[4] == std::pair<double, double>(0, 3));
    CHECK(scores[5] == std::pair<double, double>(0, 4));
    CHECK(scores[6] == std::pair<double, double>(3, 3));
    CHECK(scores[7] == std::pair<double, double>(3, 6));
    // Stages 8 and 9 have no check in the example: nothing scored, nothing to score.
    CHECK(scores[8] == std::pair<double, double>(0, 0));
    CHECK(scores[9] == std::pair<double, double>(0, 0));
}

TEST_CASE("GradeReport::stage_scores: a stage out of range names its check", "[report]") {
    GradeReport report;
    report.checks.resize(1);
    report.checks[0].id = "stage12.unit.nothing";
    report.checks[0].stage = 12;
    CHECK_THROWS_WITH(report.stage_scores(), Catch::Matchers::Contains("stage12.unit.nothing") &&
                                                 Catch::Matchers::Contains("stage 12"));
}
