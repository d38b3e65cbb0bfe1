#include "grader/report/junit_xml.h"

#include "app/report/report_text.h"
#include "base/testing/catch.h"
#include "report_example.h"
#include "xml_document.h"

using namespace raystep::grade;
using raystep::testing::example_report;
using raystep::testing::kHiddenSecret;
using raystep::testing::kHostile;
using raystep::testing::XmlDocument;

namespace {

using Strings = std::vector<std::string>;

// The JUnit schema, written for these tests (junit_schema.xsd).
const std::filesystem::path kJunitSchema = RAYSTEP_JUNIT_SCHEMA;

}  // namespace

TEST_CASE("junit_xml: well-formed, with the counts of every suite", "[report]") {
    const XmlDocument xml(junit_xml(example_report(), Audience::instructor));
    INFO(xml.errors());
    REQUIRE(xml.well_formed());
    // 12 checks: failed 3 and not implemented 1 are failures; crashed, timed out and did not
    // compile are errors; nothing is skipped.
    CHECK(xml.values("/testsuites/@tests") == Strings{"12"});
    CHECK(xml.values("/testsuites/@failures") == Strings{"4"});
    CHECK(xml.values("/testsuites/@errors") == Strings{"3"});
    CHECK(xml.count("//@skipped") == 0);
    CHECK(xml.values("/testsuites/@time") == Strings{"44.350"});
    CHECK(xml.values("/testsuites/testsuite/@name") == Strings{"stage 1", "stage 2", "stage 3",
                                                               "stage 4", "stage 5", "stage 6",
                                                               "stage 7", "pipeline"});
    CHECK(xml.values("//testsuite[@name='stage 3']/@tests") == Strings{"3"});
    CHECK(xml.values("//testsuite[@name='stage 3']/@failures") == Strings{"2"});
    CHECK(xml.values("//testsuite[@name='stage 3']/@errors") == Strings{"1"});
    CHECK(xml.values("//testsuite[@name='stage 3']/properties/property[@name='score']/@value") ==
          Strings{"1.5"});
    CHECK(xml.count("//skipped") == 0);
    // The suites' counts add up to the whole.
    std::size_t testcases = 0;
    for (const std::string& count : xml.values("/testsuites/testsuite/@tests")) {
        testcases += std::stoul(count);
    }
    CHECK(testcases == xml.count("//testcase"));
}

TEST_CASE("junit_xml: each outcome as a failure, an error or nothing", "[report]") {
    const XmlDocument xml(junit_xml(example_report(), Audience::instructor));
    REQUIRE(xml.well_formed());
    const auto testcase = [](const std::string& id) { return "//testcase[@name='" + id + "']"; };
    CHECK(xml.values(testcase("stage3.oracle.shared-edges") + "/@classname") ==
          Strings{"stage 3.oracle"});
    CHECK(xml.values(testcase("pipeline.render.cse167-scene7") + "/@classname") ==
          Strings{"pipeline.render"});
    CHECK(xml.count(testcase("stage1.unit.dot") + "/*[self::failure or self::error]") == 0);
    CHECK(xml.values(testcase("stage3.oracle.shared-edges") + "/failure/@type") ==
          Strings{"failed"});
    CHECK(xml.values(testcase("stage2.unit.perspective") + "/failure/@type") ==
          Strings{"not implemented"});
    CHECK(xml.values(testcase("stage3.unit.sphere") + "/error/@type") == Strings{"crashed"});
    CHECK(xml.values(testcase("stage4.speed.bvh-sah") + "/error/@type") == Strings{"timed out"});
    CHECK(xml.values(testcase("stage5.unit.rotate") + "/error/@type") ==
          Strings{"did not compile"});
    CHECK(xml.values(testcase("stage3.oracle.shared-edges") + "/failure/@message") ==
          Strings{"97 of 100 cases right; 3 false misses (leaks through an edge)"});
    CHECK_THAT(xml.values(testcase("stage5.unit.rotate") + "/error").at(0),
               Catch::Matchers::Contains("&& <iostream>"));
    CHECK_THAT(xml.values(testcase("stage1.unit.dot") + "/system-out").at(0),
               Catch::Matchers::StartsWith("passed, 2 / 2 points"));
}

TEST_CASE("junit_xml: a submission's hostile output reads back as text", "[report]") {
    const XmlDocument xml(junit_xml(example_report(), Audience::student));
    REQUIRE(xml.well_formed());
    CHECK_THAT(xml.values("//testcase[@name='stage3.oracle.shared-edges']/failure").at(0),
               Catch::Matchers::Contains(displayable_text(kHostile)));

    // In every attribute too: id, kind, summary, student.
    GradeReport report;
    report.student = kHostile;
    CheckResult check;
    check.id = kHostile + "\nsecond line";
    check.kind = kHostile;
    check.summary = kHostile;
    check.details = kHostile;
    check.stage = 2;
    report.checks.push_back(check);
    const XmlDocument hostile(junit_xml(report, Audience::student));
    INFO(hostile.errors());
    REQUIRE(hostile.well_formed());
    CHECK(hostile.values("//testcase/@name") == Strings{displayable_text(check.id)});
    CHECK(hostile.values("//testcase/@classname") ==
          Strings{"stage 2." + displayable_text(kHostile)});
    CHECK(hostile.values("//failure/@message") == Strings{displayable_text(kHostile)});
    CHECK(hostile.values("/testsuites/@name") ==
          Strings{"raystep-grade: " + displayable_text(kHostile)});
}

TEST_CASE("junit_xml: the student's view leaves the withheld checks out", "[report]") {
    const std::string text = junit_xml(example_report(), Audience::student);
    CHECK_THAT(text, !Catch::Matchers::Contains(kHiddenSecret));
    const XmlDocument xml(text);
    REQUIRE(xml.well_formed());
    CHECK(xml.values("/testsuites/@tests") == Strings{"9"});
    CHECK(xml.values("/testsuites/@failures") == Strings{"3"});
    CHECK(xml.count("//testsuite[@name='stage 6']") == 0);
}

TEST_CASE("junit_xml: valid against the JUnit schema CI reporters read, in both views",
          "[report]") {
    GradeReport with_problem = example_report();
    with_problem.intake_problem = "not an archive: " + kHostile;
    for (const GradeReport& report : {example_report(), with_problem, GradeReport{}}) {
        for (const Audience audience : {Audience::student, Audience::instructor}) {
            const XmlDocument xml(junit_xml(report, audience));
            CAPTURE(report.intake_problem, audience == Audience::student);
            CHECK(xml.schema_violations(kJunitSchema) == "");
        }
    }
}

TEST_CASE("junit_xml: the schema test rejects what CI reporters reject", "[report]") {
    // What the schema test would let through if it could not fail: a skipped count on
    // <testsuites>, a testcase with no time, an attribute of our own.
    const std::string good = junit_xml(example_report(), Audience::instructor);
    CHECK(XmlDocument(good).schema_violations(kJunitSchema) == "");
    const auto changed = [&](const std::string& from, const std::string& to) {
        std::string text = good;
        REQUIRE(text.find(from) != std::string::npos);
        text.replace(text.find(from), from.size(), to);
        return XmlDocument(text).schema_violations(kJunitSchema);
    };
    CHECK_THAT(changed("<testsuites ", "<testsuites skipped=\"0\" "),
               Catch::Matchers::Contains("skipped"));
    CHECK_THAT(changed("name=\"stage1.unit.dot\" time=\"0.250\"", "name=\"stage1.unit.dot\""),
               Catch::Matchers::Contains("time"));
    CHECK_THAT(changed("<testcase ", "<testcase score=\"2\" "), Catch::Matchers::Contains("score"));
}

TEST_CASE("junit_xml: every testsuite and testcase has its time", "[report]") {
    const GradeReport report = example_report();
    const XmlDocument xml(junit_xml(report, Audience::instructor));
    REQUIRE(xml.well_formed());
    CHECK(xml.count("//testsuite[not(@time)] | //testcase[not(@time)]") == 0);
    // The checks' own seconds, and per stage their sum: stage 3's checks are the 4th to 6th.
    CHECK(xml.values("//testcase[@name='stage1.unit.dot']/@time") == Strings{"0.250"});
    CHECK(xml.values("//testsuite[@name='stage 3']/@time") == Strings{"3.750"});
}

TEST_CASE("junit_xml: an intake problem is an error of its own suite, in both views", "[report]") {
    GradeReport report = example_report();
    report.intake_problem = "over the unpacked-bytes budget (3 GB unpacked from a 3 MB zip)";
    for (const Audience audience : {Audience::student, Audience::instructor}) {
        const XmlDocument xml(junit_xml(report, audience));
        REQUIRE(xml.well_formed());
        CHECK(xml.values("/testsuites/testsuite[1]/@name") == Strings{"intake"});
        CHECK(xml.values("//testsuite[@name='intake']/testcase/error/@message") ==
              Strings{"The submission's files could not all be taken: over the unpacked-bytes "
                      "budget (3 GB unpacked from a 3 MB zip)"});
        // Counted with the checks, so that the dashboard's totals show it.
        const std::size_t checks = audience == Audience::student ? 9 : 12;
        CHECK(xml.values("/testsuites/@tests") == Strings{std::to_string(checks + 1)});
        CHECK(xml.values("/testsuites/@errors") == Strings{"4"});
    }
    CHECK(XmlDocument(junit_xml(example_report(), Audience::student))
              .count("//testsuite[@name='intake']") == 0);
}
