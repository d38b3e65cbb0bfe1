#include "grader/report/gradescope_results.h"

#include <cmath>
#include <set>

#include "app/report/audience.h"
#include "app/report/report_text.h"
#include "base/testing/catch.h"
#include "report_example.h"

using namespace raystep::grade;
using raystep::testing::example_report;
using raystep::testing::kHiddenSecret;
using raystep::testing::kHostile;

namespace {

// What Gradescope reads: the JSON as written to results.json and parsed back.
nlohmann::json gradescope_written(const GradeReport& report) {
    return nlohmann::json::parse(gradescope_results(report).dump(2));
}

}  // namespace

// https://gradescope-autograders.readthedocs.io/en/latest/specs/, "Output format".
TEST_CASE("gradescope_results: the top level has the specification's fields and types",
          "[report]") {
    const nlohmann::json results = gradescope_written(example_report());
    REQUIRE(results.is_object());
    CHECK(results.at("score").is_number());
    CHECK(results.at("score") == 16.5);
    CHECK(results.at("execution_time").is_number_integer());
    // The student's time, rounded up: intake and build, and the shown checks' times alone.
    const GradeReport seen = seen_by(example_report(), Audience::student);
    double seconds = seen.times.intake + seen.times.build;
    for (const CheckResult& check : seen.checks)
        seconds += check.seconds;
    CHECK(results.at("execution_time") == static_cast<long>(std::ceil(seconds)));
    CHECK(results.at("execution_time") < 44);  // the whole run, withheld checks too: 44.35 s
    CHECK(results.at("output").is_string());
    CHECK(results.at("output_format") == "text");
    CHECK(results.at("test_output_format") == "text");
    CHECK(results.at("test_name_format") == "text");
    CHECK(results.at("visibility") == "visible");
    CHECK(results.at("stdout_visibility") == "hidden");
    CHECK(results.at("tests").is_array());
    const std::set<std::string> known = {"score",         "execution_time",     "output",
                                         "output_format", "test_output_format", "test_name_format",
                                         "visibility",    "stdout_visibility",  "extra_data",
                                         "tests",         "leaderboard"};
    for (const auto& [key, value] : results.items()) {
        CAPTURE(key);
        CHECK(known.count(key) == 1);
    }
}

TEST_CASE("gradescope_results: one test per check, in order, with the specification's fields",
          "[report]") {
    const GradeReport report = example_report();
    const nlohmann::json tests = gradescope_written(report).at("tests");
    REQUIRE(tests.size() == report.checks.size());
    const std::set<std::string> visibilities = {"visible", "hidden", "after_due_date",
                                                "after_published"};
    double total = 0.0;
    for (std::size_t k = 0; k < tests.size(); ++k) {
        const nlohmann::json& test = tests[k];
        const CheckResult& check = report.checks[k];
        CAPTURE(check.id);
        CHECK(test.at("score").is_number());
        CHECK(test.at("max_score").is_number());
        CHECK(test.at("score") == check.score);
        CHECK(test.at("max_score") == check.max_score);
        CHECK(test.at("name").is_string());
        CHECK(test.at("name_format") == "text");
        CHECK(test.at("number").is_string());
        CHECK(test.at("output").is_string());
        CHECK(test.at("output_format") == "text");
        CHECK(test.at("tags").is_array());
        CHECK(visibilities.count(test.at("visibility").get<std::string>()) == 1);
        CHECK(test.at("visibility") == visibility_name(check.visibility));
        CHECK(test.at("status") == (check.outcome == Outcome::passed ? "passed" : "failed"));
        CHECK(test.at("extra_data").at("id") == check.id);
        total += test.at("score").get<double>();
    }
    CHECK(total == gradescope_written(report).at("score").get<double>());
}

TEST_CASE("gradescope_results: numbers, names and outputs of individual checks", "[report]") {
    const nlohmann::json tests = gradescope_written(example_report()).at("tests");
    CHECK(tests[0].at("number") == "1.1");
    CHECK(tests[1].at("number") == "1.2");
    CHECK(tests[3].at("number") == "3.1");
    CHECK(tests[5].at("number") == "3.3");
    CHECK(tests[11].at("number") == "0.1");
    CHECK(tests[3].at("name") == "rays through shared edges of closed meshes");
    CHECK(tests[3].at("tags") == nlohmann::json({"stage 3", "oracle"}));
    const std::string output = tests[3].at("output");
    CHECK_THAT(output, Catch::Matchers::StartsWith("failed: 97 of 100 cases right"));
    CHECK_THAT(output, Catch::Matchers::Contains("reproduce: raystep check --stage 3 --family "
                                                 "shared-edges --case 42"));
    CHECK_THAT(output, Catch::Matchers::Contains(displayable_text(kHostile)));
    // Gradescope shows the output to the student: never the instructor's command.
    for (const nlohmann::json& test : tests)
        CHECK_THAT(test.at("output").get<std::string>(),
                   !Catch::Matchers::Contains("raystep-grade"));
    CHECK(tests[3].at("extra_data").at("metrics").at("false_misses") == 3);
    CHECK(tests[5].at("visibility") == "hidden");
    CHECK_THAT(tests[7].at("output").get<std::string>(),
               Catch::Matchers::Contains("'cos_theta' was not declared"));
}

TEST_CASE("gradescope_results: the output every student sees leaves the withheld checks out",
          "[report]") {
    const std::string output = gradescope_written(example_report()).at("output");
    CHECK_THAT(output, !Catch::Matchers::Contains(kHiddenSecret));
    CHECK_THAT(output, Catch::Matchers::Contains("  total     12.5 / 32   3 of 9\n"));
    CHECK_THAT(output, Catch::Matchers::Contains("3 checks are graded but not shown yet"));
}

TEST_CASE("gradescope_results: hostile bytes and NaN metrics still make valid JSON", "[report]") {
    GradeReport report;
    CheckResult check;
    check.id = kHostile;
    check.name = kHostile;
    check.summary = kHostile;
    check.details = kHostile;
    check.metrics = {{"psnr", std::numeric_limits<double>::infinity()},
                     {"rmse", std::numeric_limits<double>::quiet_NaN()}};
    report.checks.push_back(check);
    const std::string text = gradescope_results(report).dump();
    CHECK(displayable_text(text) == text);
    const nlohmann::json back = nlohmann::json::parse(text);
    CHECK(back.at("tests")[0].at("extra_data").at("metrics").at("psnr").is_null());
    CHECK(back.at("tests")[0].at("name") == displayable_text(kHostile));
}
