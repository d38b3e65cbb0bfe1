#include "app/report/audience.h"

#include "base/testing/catch.h"
#include "report_example.h"

using namespace raystep::grade;
using raystep::testing::example_report;

TEST_CASE("shown_to: a student sees only visible checks, the instructor all", "[report]") {
    CheckResult check;
    for (const Visibility visibility : {Visibility::visible, Visibility::hidden,
                                        Visibility::after_due_date, Visibility::after_published}) {
        CAPTURE(visibility_name(visibility));
        check.visibility = visibility;
        CHECK(shown_to(check, Audience::instructor));
        CHECK(shown_to(check, Audience::student) == (visibility == Visibility::visible));
    }
}

TEST_CASE("seen_by: the student's report drops the withheld checks and their points", "[report]") {
    const GradeReport report = example_report();
    const GradeReport student = seen_by(report, Audience::student);
    CHECK(student.checks.size() == report.checks.size() - 3);
    CHECK(student.score() == 12.5);
    CHECK(student.max_score() == 32.0);
    CHECK(student.student == report.student);
    for (const CheckResult& check : student.checks)
        CHECK(check.visibility == Visibility::visible);
    CHECK(seen_by(report, Audience::instructor).checks.size() == report.checks.size());
}

TEST_CASE("seen_by: the student's times leave out the withheld checks' time", "[report]") {
    GradeReport report = example_report();
    report.times = {0.5, 2.0, 100.0, 1.5};
    double shown = 0.0;
    for (CheckResult& check : report.checks) {
        // A withheld check that takes long, as a submission can make one whose input says so.
        check.seconds = check.visibility == Visibility::visible ? 0.25 : 90.0;
        if (check.visibility == Visibility::visible) shown += check.seconds;
    }
    const GradeReport student = seen_by(report, Audience::student);
    CHECK(student.times.checks == shown);
    CHECK(student.times.reports == 0.0);
    CHECK(student.times.intake == 0.5);
    CHECK(student.times.build == 2.0);
    const GradeReport instructor = seen_by(report, Audience::instructor);
    CHECK(instructor.times.checks == 100.0);
    CHECK(instructor.times.reports == 1.5);
}
