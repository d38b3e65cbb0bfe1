#include "grader/report/check_findings.h"

#include "core/testing/catch.h"
#include "grader/report/report_text.h"
#include "report_example.h"

using namespace raystep::grade;
using raystep::testing::example_report;
using raystep::testing::find_check;
using raystep::testing::kHostile;

TEST_CASE("check_findings: every counterexample with its command, then details and metrics",
          "[report]") {
    const GradeReport report = example_report();
    const std::string text =
        check_findings(find_check(report, "stage3.oracle.shared-edges"), 100000);
    CHECK_THAT(text, Catch::Matchers::StartsWith("Counterexample 1 of 3\n  input:     ray"));
    for (const char* command : {"--case 17", "--case 42", "--case 64"}) {
        CHECK_THAT(text, Catch::Matchers::Contains(std::string("  reproduce: raystep check "
                                                               "--stage 3 --family shared-edges ") +
                                                   command));
    }
    CHECK_THAT(text, Catch::Matchers::Contains("  got:       " + displayable_text(kHostile)));
    CHECK_THAT(text, Catch::Matchers::Contains("Metrics\n  false_misses: 3\n"));
    CHECK(displayable_text(text) == text);

    const std::string crash = check_findings(find_check(report, "stage3.unit.sphere"), 100000);
    CHECK_THAT(crash, Catch::Matchers::StartsWith("Details\nsignal 11 (SIGSEGV)"));
    CHECK(check_findings(find_check(report, "stage1.unit.dot"), 100000).empty());
}

TEST_CASE("check_findings: a submission printing megabytes gives a short text", "[report]") {
    CheckResult check;
    check.details = std::string(5'000'000, 'x');
    check.counterexamples.assign(20, {std::string(1'000'000, 'i'), "e", "g", "r"});
    const std::string text = check_findings(check, 4000);
    CHECK(text.size() < 4100);
    CHECK_THAT(text, Catch::Matchers::EndsWith("more bytes]"));
}
