#include "grader/report/student_results.h"

#include "app/report/report_text.h"
#include "base/testing/catch.h"
#include "report_example.h"

using namespace raystep::grade;
using raystep::testing::example_report;
using raystep::testing::kHiddenSecret;
using raystep::testing::kHostile;

namespace {

// What a student's script reads: the JSON as written and parsed back.
nlohmann::json student_written(const GradeReport& report) {
    return nlohmann::json::parse(student_results(report).dump(2));
}

}  // namespace

TEST_CASE("student_results: only the checks a student is shown, and how many are not", "[report]") {
    const GradeReport report = example_report();
    const std::string text = student_results(report).dump();
    CHECK_THAT(text, !Catch::Matchers::Contains(kHiddenSecret));
    for (const char* withheld : {"stage6.render.shadows", "stage7.unit.depth",
                                 "SHADOWS-after-due-date", "PUBLISHED-depth-input"}) {
        CHECK_THAT(text, !Catch::Matchers::Contains(withheld));
    }
    const nlohmann::json results = student_written(report);
    CHECK(results.at("checks").size() == 9);
    CHECK(results.at("checks_not_shown") == 3);
    CHECK(results.at("score") == 12.5);
    CHECK(results.at("max_score") == 32);
    CHECK(results.at("intake_problem") == "");
    double total = 0.0;
    for (const nlohmann::json& check : results.at("checks"))
        total += check.at("score").get<double>();
    CHECK(total == 12.5);
}

TEST_CASE("student_results: each stage's sums, in the order a student meets them", "[report]") {
    const nlohmann::json stages = student_written(example_report()).at("stages");
    REQUIRE(stages.size() == 7);  // stage 6 has only a withheld check
    CHECK(stages[0] == nlohmann::json({{"stage", 1},
                                       {"name", "stage 1"},
                                       {"score", 5},
                                       {"max_score", 5},
                                       {"checks", 2},
                                       {"passed", 2}}));
    CHECK(stages[2].at("name") == "stage 3");
    CHECK(stages[2].at("max_score") == 7);  // the hidden check's 4 points left out
    CHECK(stages[6].at("name") == "pipeline");
}

TEST_CASE("student_results: a check with its counterexamples and the student's commands",
          "[report]") {
    const nlohmann::json checks = student_written(example_report()).at("checks");
    const nlohmann::json& edges = checks[3];
    CHECK(edges.at("id") == "stage3.oracle.shared-edges");
    CHECK(edges.at("outcome") == "failed");
    CHECK(edges.at("passed") == false);
    CHECK(edges.at("score") == 1.5);
    CHECK(edges.at("seconds") == 1.0);
    CHECK(edges.at("metrics").at("false_misses") == 3);
    REQUIRE(edges.at("counterexamples").size() == 3);
    CHECK(edges.at("counterexamples")[0].at("reproduce") ==
          "raystep check --stage 3 --family shared-edges --case 17");
    CHECK(edges.at("counterexamples")[1].at("got") == displayable_text(kHostile));
    CHECK(edges.at("counterexamples")[2].at("reproduce") == "");
    CHECK(checks[0].at("passed") == true);
    CHECK_THAT(student_written(example_report()).dump(),
               !Catch::Matchers::Contains("raystep-grade"));
}

TEST_CASE("student_results: hostile bytes and NaN metrics still make valid JSON", "[report]") {
    GradeReport report;
    report.student = kHostile;
    CheckResult check;
    check.id = kHostile;
    check.summary = kHostile;
    check.metrics = {{"psnr", std::numeric_limits<double>::infinity()}};
    check.counterexamples = {{kHostile, kHostile, std::string(100'000, 'g'), "", kHostile}};
    report.checks.push_back(check);
    const std::string text = student_results(report).dump();
    CHECK(displayable_text(text) == text);
    const nlohmann::json back = nlohmann::json::parse(text);
    CHECK(back.at("checks")[0].at("metrics").at("psnr").is_null());
    CHECK(back.at("checks")[0].at("counterexamples")[0].at("got").get<std::string>().size() <
          kMaxFieldBytes + 100);
}
