#pragma once

#include <string>

#include "grader/report/audience.h"
#include "grader/report/grade_report.h"

namespace raystep::grade {

/// The grade as JUnit XML, for CI dashboards and GitHub Classroom: <testsuites> (the submission,
/// with the grading's time) holds a <testsuite> per stage that has checks ("stage 3", or
/// "pipeline"; with its counts and its score and maximum as properties), each holding a
/// <testcase> per check (classname "stage 3.oracle", name the check's id) whose <system-out> has
/// the outcome, score and summary. A check that failed or is not implemented has a <failure>, one
/// that crashed, timed out or did not compile an <error>; their text is check_findings.h. The
/// student's view leaves out the checks a student is not shown (audience.h).
///
/// Every text is escaped (markup_escape.h): the document is well-formed XML 1.0 whatever a
/// submission wrote. The data has no time per check, so only <testsuites> has a time.
std::string junit_xml(const GradeReport& report, Audience audience);

}  // namespace raystep::grade
