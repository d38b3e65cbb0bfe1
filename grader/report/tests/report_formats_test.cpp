// What every report format must agree on: the outcome of each check, and the intake problem.
#include "app/report/console_summary.h"
#include "app/report/report_text.h"
#include "base/testing/catch.h"
#include "grader/report/gradescope_results.h"
#include "grader/report/html_report.h"
#include "grader/report/junit_xml.h"
#include "grader/report/prairielearn_results.h"
#include "grader/report/student_results.h"
#include "report_example.h"
#include "xml_document.h"

using namespace raystep::grade;
using raystep::testing::example_report;
using raystep::testing::kHostile;
using raystep::testing::XmlDocument;

namespace {

using Strings = std::vector<std::string>;

constexpr Audience kAudiences[] = {Audience::student, Audience::instructor};

CheckResult full_points_check(const std::string& id, Visibility visibility) {
    CheckResult check;
    check.id = id;
    check.stage = 1;
    check.kind = "oracle";
    check.name = "projection onto a vector";
    check.outcome = Outcome::passed;
    check.score = 3;
    check.max_score = 3;
    check.visibility = visibility;
    check.summary = "1000 of 1000 cases right";
    return check;
}

std::string html_page(const GradeReport& report, Audience audience) {
    HtmlReportOptions options;
    options.audience = audience;
    return html_report(report, {}, options);
}

}  // namespace

TEST_CASE("every report: a check with full points is passed in every format", "[report]") {
    GradeReport report;
    report.student = "alice";
    report.checks = {full_points_check("stage1.oracle.projection", Visibility::visible),
                     full_points_check("stage1.hidden", Visibility::hidden)};

    const nlohmann::json gradescope = gradescope_results(report);
    for (const nlohmann::json& test : gradescope.at("tests")) {
        CHECK(test.at("status") == "passed");
        CHECK(test.at("score") == test.at("max_score"));
    }
    // Held in a variable: a range-for over a member of a temporary reads freed memory.
    const nlohmann::json prairielearn = prairielearn_results(report, {});
    for (const nlohmann::json& test : prairielearn.at("tests")) {
        CAPTURE(test.dump());
        CHECK(test.at("points") == test.at("max_points"));
    }
    CHECK_THAT(prairielearn_results(report, {}).at("tests")[0].at("message").get<std::string>(),
               Catch::Matchers::StartsWith("passed"));
    CHECK(student_results(report).at("checks")[0].at("passed") == true);
    CHECK(student_results(report).at("checks")[0].at("outcome") == "passed");
    for (const Audience audience : kAudiences) {
        const XmlDocument junit(junit_xml(report, audience));
        REQUIRE(junit.well_formed());
        CHECK(junit.count("//failure | //error") == 0);
        CHECK(junit.values("/testsuites/@failures") == Strings{"0"});
        for (const std::string& out : junit.values("//testcase/system-out"))
            CHECK_THAT(out, Catch::Matchers::StartsWith("passed, 3 / 3 points"));

        const XmlDocument html(html_page(report, audience));
        REQUIRE(html.well_formed());
        for (const std::string& badge : html.values("//article//span[contains(@class, 'badge')]"))
            CHECK(badge == "passed");
        CHECK(html.count("//article[not(contains(@class, 'passed'))]") == 0);

        CHECK_THAT(console_summary(report, audience),
                   Catch::Matchers::Contains(
                       "  passed               3 / 3  stage1.oracle.projection: 1000 of 1000"));
    }
}

TEST_CASE("every report: each check's outcome reads the same in every format", "[report]") {
    const GradeReport report = example_report();
    const nlohmann::json gradescope = gradescope_results(report);
    const XmlDocument junit(junit_xml(report, Audience::instructor));
    const XmlDocument html(html_page(report, Audience::instructor));
    REQUIRE(junit.well_formed());
    REQUIRE(html.well_formed());
    for (std::size_t k = 0; k < report.checks.size(); ++k) {
        const CheckResult& check = report.checks[k];
        CAPTURE(check.id);
        const bool passed = check.outcome == Outcome::passed;
        CHECK((gradescope.at("tests")[k].at("status") == "passed") == passed);
        const std::string testcase = "//testcase[@name='" + check.id + "']";
        CHECK(junit.count(testcase + "/*[self::failure or self::error]") == (passed ? 0u : 1u));
        CHECK(html.values("//article[.//code[text()='" + check.id +
                          "']]//span[contains(@class, 'badge')]") ==
              Strings{outcome_name(check.outcome)});
    }
    const nlohmann::json prairielearn = prairielearn_results(report, {});
    for (const nlohmann::json& test : prairielearn.at("tests")) {
        const std::string name = test.at("name");
        if (name.find("hidden checks") != std::string::npos) continue;
        CHECK_THAT(test.at("message").get<std::string>(),
                   Catch::Matchers::StartsWith(
                       outcome_name(raystep::testing::find_check(report, name).outcome)));
    }
}

TEST_CASE("every report: an intake problem is said in every format, to both audiences",
          "[report]") {
    GradeReport with_checks = example_report();
    with_checks.intake_problem = "not an archive (a tar file named .zip): " + kHostile;
    GradeReport without_checks;
    without_checks.student = "bob";
    without_checks.intake_problem = with_checks.intake_problem;
    const std::string line = intake_problem_line(with_checks.intake_problem);
    REQUIRE_THAT(line, Catch::Matchers::StartsWith("The submission's files could not all be taken: "
                                                   "not an archive"));

    for (const GradeReport& report : {with_checks, without_checks}) {
        CAPTURE(report.checks.size());
        CHECK_THAT(gradescope_results(report).at("output").get<std::string>(),
                   Catch::Matchers::StartsWith(line + "\n"));
        CHECK_THAT(prairielearn_results(report, {}).at("message").get<std::string>(),
                   Catch::Matchers::StartsWith(line + "\n"));
        CHECK(student_results(report).at("intake_problem") == line);
        for (const Audience audience : kAudiences) {
            // Second on the console, right under who it is, before the total.
            const std::string console = console_summary(report, audience);
            CHECK(console.find("The submission's files could not all be taken: not an archive") <
                  console.find("Total: "));
            const XmlDocument html(html_page(report, audience));
            REQUIRE(html.well_formed());
            CHECK(html.values("//main/p[@class='problem']") == Strings{line});
            const XmlDocument junit(junit_xml(report, audience));
            REQUIRE(junit.well_formed());
            CHECK(junit.values("//testsuite[@name='intake']/testcase/error/@message") ==
                  Strings{line});
        }
    }

    // When nothing compiled, PrairieLearn shows format_errors, and the reason comes first there.
    GradeReport nothing_compiled = without_checks;
    CheckResult check;
    check.id = "stage1.unit";
    check.stage = 1;
    check.outcome = Outcome::did_not_compile;
    check.details = "no files";
    nothing_compiled.checks.push_back(check);
    CHECK(prairielearn_results(nothing_compiled, {}).at("format_errors") ==
          nlohmann::json({line, "no files"}));
}
