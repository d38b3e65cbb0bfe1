#include "grader/report/check_findings.h"

#include "app/report/report_text.h"
#include "base/testing/catch.h"
#include "report_example.h"

using namespace raystep::grade;
using raystep::testing::example_report;
using raystep::testing::find_check;
using raystep::testing::kHostile;

TEST_CASE("check_findings: every counterexample with its command, then details and metrics",
          "[report]") {
    const GradeReport report = example_report();
    const std::string text =
        check_findings(find_check(report, "stage3.oracle.shared-edges"), Audience::student, 100000);
    CHECK_THAT(text, Catch::Matchers::StartsWith("Counterexample 1 of 3\n  input:     ray"));
    for (const char* command : {"--case 17", "--case 42"}) {
        CHECK_THAT(text, Catch::Matchers::Contains(std::string("  reproduce: raystep check "
                                                               "--stage 3 --family shared-edges ") +
                                                   command));
    }
    CHECK_THAT(text, Catch::Matchers::Contains("  got:       " + displayable_text(kHostile)));
    CHECK_THAT(text, Catch::Matchers::Contains("Metrics\n  false_misses: 3\n"));
    CHECK(displayable_text(text) == text);

    const std::string crash =
        check_findings(find_check(report, "stage3.unit.sphere"), Audience::student, 100000);
    CHECK_THAT(crash, Catch::Matchers::StartsWith("Details\nsignal 11 (SIGSEGV)"));
    CHECK(check_findings(find_check(report, "stage1.unit.dot"), Audience::student, 100000).empty());
}

TEST_CASE(
    "check_findings: the student's commands for the student, raystep-grade's for the "
    "instructor",
    "[report]") {
    const GradeReport report = example_report();
    const CheckResult& edges = find_check(report, "stage3.oracle.shared-edges");
    const std::string student = check_findings(edges, Audience::student, 100000);
    CHECK_THAT(student, !Catch::Matchers::Contains("raystep-grade"));
    // The third counterexample has no student's command: no reproduce line at all.
    const std::string third = student.substr(student.find("Counterexample 3 of 3"));
    CHECK_THAT(third, !Catch::Matchers::Contains("reproduce"));

    const std::string instructor = check_findings(edges, Audience::instructor, 100000);
    for (const char* command : {"--case 17", "--case 42", "--case 64"}) {
        CHECK_THAT(instructor,
                   Catch::Matchers::Contains(std::string("  reproduce: raystep-grade submission "
                                                         "'submissions/alice & bob.zip' --check "
                                                         "stage3.oracle.shared-edges ") +
                                             command));
    }
}

TEST_CASE("check_findings: a submission printing megabytes gives a short text", "[report]") {
    CheckResult check;
    check.details = std::string(5'000'000, 'x');
    check.counterexamples.assign(20, {std::string(1'000'000, 'i'), "e", "g", "r", "s"});
    const std::string text = check_findings(check, Audience::student, 4000);
    CHECK(text.size() < 4100);
    CHECK_THAT(text, Catch::Matchers::EndsWith("more bytes]"));
}
