#include "app/report/console_summary.h"

#include <sstream>

#include "app/report/report_text.h"
#include "base/testing/catch.h"
#include "report_example.h"

using namespace raystep::grade;
using raystep::testing::example_report;
using raystep::testing::kHiddenSecret;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

std::size_t columns(const std::string& line) {
    std::size_t count = 0;
    for (const char c : line)
        count += (static_cast<unsigned char>(c) & 0xC0) != 0x80 ? 1 : 0;
    return count;
}

}  // namespace

TEST_CASE("console_summary: the student's view has no withheld check and says how many",
          "[report]") {
    const std::string text = console_summary(example_report(), Audience::student);
    CHECK_THAT(text, !Catch::Matchers::Contains(kHiddenSecret));
    CHECK_THAT(text, !Catch::Matchers::Contains("stage6.render.shadows"));
    CHECK_THAT(text, !Catch::Matchers::Contains("stage7.unit.depth"));
    CHECK_THAT(text, !Catch::Matchers::Contains("[hidden]"));
    CHECK_THAT(text, Catch::Matchers::Contains("Total: 12.5 / 32 points\n"));
    CHECK_THAT(text, Catch::Matchers::Contains("\n3 checks are not shown here"));
}

TEST_CASE("console_summary: the instructor's view shows every check with its visibility",
          "[report]") {
    const std::string text = console_summary(example_report(), Audience::instructor);
    CHECK_THAT(text, Catch::Matchers::Contains("Total: 16.5 / 40 points\n"));
    CHECK_THAT(text, Catch::Matchers::Contains("[hidden]: 0 of 50 right on " + kHiddenSecret));
    CHECK_THAT(text, Catch::Matchers::Contains("stage6.render.shadows [after due date]"));
    CHECK_THAT(text, Catch::Matchers::Contains("stage7.unit.depth [after published]"));
    CHECK_THAT(text, !Catch::Matchers::Contains("not shown here"));
}

TEST_CASE("console_summary: the stage table, then each check under its stage", "[report]") {
    const std::string text = console_summary(example_report(), Audience::instructor);
    CHECK_THAT(text,
               Catch::Matchers::StartsWith("raystep-grade: alice <b>& \"bob\" (submissions/"));
    CHECK_THAT(text, Catch::Matchers::Contains("\n\n  stage         score   passed\n"
                                               "  stage 1       5 / 5   2 of 2\n"));
    CHECK_THAT(text, Catch::Matchers::Contains("  stage 3    1.5 / 11   0 of 3\n"));
    CHECK_THAT(text, Catch::Matchers::Contains("  pipeline      4 / 4   1 of 1\n"
                                               "  total     16.5 / 40   5 of 12\n"));
    CHECK_THAT(text, Catch::Matchers::Contains("\nstage 1\n  passed               2 / 2  "
                                               "stage1.unit.dot: 12 of 12 cases right\n"));
    // The pipeline comes after stage 7.
    CHECK(text.find("\npipeline\n") > text.find("\nstage 7\n"));
}

TEST_CASE("console_summary: a failed check shows its first counterexample and how to rerun it",
          "[report]") {
    const std::string text = console_summary(example_report(), Audience::student);
    CHECK_THAT(text, Catch::Matchers::Contains(
                         "      reproduce  raystep check --stage 3 --family shared-edges --case "
                         "17\n      and 2 more counterexamples\n"));
    CHECK_THAT(text, !Catch::Matchers::Contains("--case 42"));
    // The student's commands only: raystep-grade is the instructor's.
    CHECK_THAT(text, !Catch::Matchers::Contains("raystep-grade submission"));
    CHECK_THAT(console_summary(example_report(), Audience::instructor),
               Catch::Matchers::Contains("      reproduce  raystep-grade submission "
                                         "'submissions/alice & bob.zip' --check "
                                         "stage3.oracle.shared-edges --case 17 --instructor\n"));
    // Crashes, timeouts and compile errors show their details; a long compiler output its first
    // 8 lines.
    CHECK_THAT(text, Catch::Matchers::Contains("      signal 11 (SIGSEGV)"));
    CHECK_THAT(text, Catch::Matchers::Contains("      killed after 20.0 s"));
    CHECK_THAT(text, Catch::Matchers::Contains("      (8 more lines)\n"));
    CHECK_THAT(text, Catch::Matchers::Contains(
                         "  not implemented      0 / 4  stage2.unit.perspective: stage 2: "
                         "perspective_ray\n                              "
                         "is not implemented yet, see docs/stage2.md\n"));
}

TEST_CASE("console_summary: fits 80 columns and shows nothing that acts on a terminal",
          "[report]") {
    for (const Audience audience : {Audience::student, Audience::instructor}) {
        const std::string text = console_summary(example_report(), audience);
        CHECK(displayable_text(text) == text);  // no escape, no carriage return, valid UTF-8
        for (const std::string& line : lines_of(text)) {
            CAPTURE(line);
            // A reproduce command is the one thing never broken.
            if (line.find("reproduce") == std::string::npos) CHECK(columns(line) <= kConsoleWidth);
            if (!line.empty()) CHECK(line.back() != ' ');
        }
    }
}

TEST_CASE("console_summary: an empty report still says who and the total", "[report]") {
    GradeReport report;
    report.student = "nobody";
    CHECK(console_summary(report, Audience::student) ==
          "raystep-grade: nobody\nTotal: 0 / 0 points\n\n"
          "  stage     score   passed\n"
          "  total     0 / 0   0 of 0\n");
}
