#pragma once

#include <nlohmann/json.hpp>

#include "app/report/grade_report.h"

namespace raystep::grade {

/// The grade as the student may see it, as JSON (results.json in the student's folder), for a
/// student's own scripts and CI: only the checks a student is shown (audience.h), so that
/// nothing in it names a withheld check or its inputs; only a count says how many there are.
///
/// - "student", "submission", "intake_problem" (the sentence of report_text.h, or "");
/// - "score" and "max_score": the sums of the checks shown; "checks_not_shown": how many are not;
/// - "stages": for each stage with checks shown, in the order a student meets them (the
///   pipeline last), "stage" (0 is the pipeline), "name", "score", "max_score", "checks" and
///   "passed";
/// - "checks": in report order, "id", "stage", "kind", "name", "outcome" (outcome_name),
///   "passed" (the outcome is passed), "score", "max_score", "summary", "seconds", "metrics"
///   (null where not finite: JSON has no NaN or infinity), "details" and "counterexamples", each
///   with "input", "expected", "got" and "reproduce": the student's command (reproduce_command,
///   audience.h), "" when there is none;
/// - "times": the grading's phases in seconds.
///
/// Every string is displayable (report_text.h) and clipped as the other reports clip it; no image
/// paths, since the images stay in the instructor's folder and the student's HTML page carries
/// its own.
nlohmann::json student_results(const GradeReport& report);

}  // namespace raystep::grade
