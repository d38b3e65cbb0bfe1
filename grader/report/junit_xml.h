#pragma once

#include <string>

#include "app/report/audience.h"
#include "app/report/grade_report.h"

namespace raystep::grade {

/// The grade as JUnit XML, for CI dashboards and GitHub Classroom, in the schema CI reporters read
/// (the Ant and Jenkins JUnit schema): <testsuites> (the submission, with its counts and the
/// grading's time) holds a <testsuite> per stage that has checks ("stage 3", or "pipeline"; with
/// its counts, the sum of its checks' times, and its score and maximum as properties), each
/// holding a <testcase> per check (classname "stage 3.oracle", name the check's id, time the
/// check's seconds) whose <system-out> has the outcome, score and summary. A check that failed or
/// is not implemented has a <failure>, one that crashed, timed out or did not compile an <error>;
/// their text is check_findings.h for the audience. When the submission's files could not all be
/// taken (GradeReport::intake_problem), a first suite "intake" holds one testcase whose <error>
/// says why, for both audiences. The student's view leaves out the checks a student is not shown
/// (audience.h).
///
/// Every text is escaped (markup_escape.h): the document is well-formed XML 1.0 whatever a
/// submission wrote. No attribute outside the schema: no skipped count, since nothing is skipped.
std::string junit_xml(const GradeReport& report, Audience audience);

}  // namespace raystep::grade
