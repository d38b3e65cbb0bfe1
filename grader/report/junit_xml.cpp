#include "grader/report/junit_xml.h"

#include <cstdio>
#include <string_view>

#include "app/report/report_text.h"
#include "grader/report/check_findings.h"
#include "grader/report/markup_escape.h"

namespace raystep::grade {

namespace {

// Text of one failure: a CI page shows it whole, so keep it to a few screens.
constexpr std::size_t kMaxFailureBytes = 16000;

// count()'s stage for every check of the report.
constexpr int kAllStages = -1;

// The suite, and its testcase's class, of an intake problem.
constexpr std::string_view kIntakeSuite = "intake";

struct Counts {
    int tests = 0;
    int failures = 0;
    int errors = 0;
};

// An answer that is wrong, and a stage left unwritten, are failures: the student's code did what
// it was asked and got it wrong, or did not do it. Not implemented is not a skip: a skip reads as
// "not applicable, nothing lost" on a CI dashboard and would show a submission missing a stage as
// green. A crash, a timeout or a compile error stopped the check before it could judge anything:
// JUnit's error.
bool is_failure(Outcome outcome) {
    return outcome == Outcome::failed || outcome == Outcome::not_implemented;
}
bool is_error(Outcome outcome) {
    return outcome == Outcome::crashed || outcome == Outcome::timed_out ||
           outcome == Outcome::did_not_compile;
}

Counts count(const GradeReport& report, int stage) {
    Counts counts;
    for (const CheckResult& check : report.checks) {
        if (stage != kAllStages && check.stage != stage) continue;
        ++counts.tests;
        if (is_failure(check.outcome)) ++counts.failures;
        if (is_error(check.outcome)) ++counts.errors;
    }
    return counts;
}

// No skipped count: nothing the grader does is ever skipped (see is_failure), and the schema
// has none on <testsuites>.
std::string count_attributes(const Counts& counts) {
    return " tests=\"" + std::to_string(counts.tests) + "\" failures=\"" +
           std::to_string(counts.failures) + "\" errors=\"" + std::to_string(counts.errors) + "\"";
}

// A time attribute in seconds with millisecond digits; a negative or NaN time (a clock that went
// back, a field never set) is 0, since the schema's time is a non-negative decimal.
std::string time_attribute(double seconds) {
    char text[48];
    std::snprintf(text, sizeof text, "%.3f", seconds >= 0.0 && seconds < 1e12 ? seconds : 0.0);
    return std::string(" time=\"") + text + "\"";
}

std::string property(const std::string& name, const std::string& value) {
    return "      <property name=\"" + name + "\" value=\"" + markup_attribute(value) + "\"/>\n";
}

std::string testcase(const CheckResult& check, Audience audience) {
    std::string xml = "    <testcase classname=\"" +
                      markup_attribute(stage_label(check.stage) + "." + check.kind) + "\" name=\"" +
                      markup_attribute(check.id) + "\"" + time_attribute(check.seconds) + ">\n";
    if (check.outcome != Outcome::passed) {
        const char* element = is_error(check.outcome) ? "error" : "failure";
        xml += std::string("      <") + element + " message=\"" +
               markup_attribute(clipped_text(check.summary, kMaxFieldBytes)) + "\" type=\"" +
               markup_attribute(outcome_name(check.outcome)) + "\">" +
               markup_text(check_findings(check, audience, kMaxFailureBytes)) + "</" + element +
               ">\n";
    }
    std::string out =
        outcome_name(check.outcome) + ", " + score_out_of(check.score, check.max_score) + " points";
    if (!check.name.empty()) out += "\n" + check.name;
    if (!check.summary.empty()) out += "\n" + clipped_text(check.summary, kMaxFieldBytes);
    xml += "      <system-out>" + markup_text(out) + "</system-out>\n";
    return xml + "    </testcase>\n";
}

// The suite that says why the submission's files could not all be taken: one testcase with an
// <error>, so that every CI page shows it in red with the stages' failures.
std::string intake_suite(const GradeReport& report) {
    const std::string line = intake_problem_line(report.intake_problem);
    return "  <testsuite name=\"" + std::string(kIntakeSuite) + "\"" + count_attributes({1, 0, 1}) +
           time_attribute(report.times.intake) + ">\n    <testcase classname=\"" +
           std::string(kIntakeSuite) + "\" name=\"submission files\"" +
           time_attribute(report.times.intake) + ">\n      <error message=\"" +
           markup_attribute(line) + "\" type=\"intake problem\">" + markup_text(line) +
           "</error>\n    </testcase>\n" + "  </testsuite>\n";
}

}  // namespace

std::string junit_xml(const GradeReport& report, Audience audience) {
    const GradeReport seen = seen_by(report, audience);
    const PhaseTimes& times = seen.times;
    const std::string who = report.student.empty() ? report.submission : report.student;
    const bool intake_problem = !report.intake_problem.empty();

    Counts all = count(seen, kAllStages);
    if (intake_problem) {
        ++all.tests;
        ++all.errors;
    }
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml += "<testsuites name=\"" + markup_attribute("raystep-grade: " + who) + "\"" +
           count_attributes(all) +
           time_attribute(times.intake + times.build + times.checks + times.reports) + ">\n";
    if (intake_problem) xml += intake_suite(report);
    const std::vector<std::pair<double, double>> scores = seen.stage_scores();
    for (const int stage : kStageReportOrder) {
        const Counts counts = count(seen, stage);
        if (counts.tests == 0) continue;
        const auto& [score, max_score] = scores[static_cast<std::size_t>(stage)];
        double seconds = 0.0;
        std::string testcases;
        for (const CheckResult& check : seen.checks) {
            if (check.stage != stage) continue;
            testcases += testcase(check, audience);
            seconds += check.seconds;
        }
        xml += "  <testsuite name=\"" + stage_label(stage) + "\"" + count_attributes(counts) +
               time_attribute(seconds) + ">\n    <properties>\n" +
               property("score", score_text(score)) + property("max_score", score_text(max_score)) +
               "    </properties>\n" + testcases + "  </testsuite>\n";
    }
    return xml + "</testsuites>\n";
}

}  // namespace raystep::grade
