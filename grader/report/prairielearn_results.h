#pragma once

#include <nlohmann/json.hpp>

#include "grader/report/grade_report.h"

namespace raystep::grade {

/// PrairieLearn's external grader results.json for the grade, as its documentation has it
/// (https://prairielearn.readthedocs.io/en/latest/externalGrading/, "Grading results"):
///
/// - "gradable": false only when the report has checks and none of them compiled: PrairieLearn
///   then awards and takes no points and gives the attempt back, as its documentation intends
///   for a syntax error, with the compilers' first lines in "format_errors". A stage that does not
///   compile beside stages that do is graded: it scores zero and the others keep their points.
/// - "score": the total over the maximum, in [0, 1]; 0 when there is nothing to score.
/// - "message": the points in words; "output": the stage table (console_summary.h).
/// - "tests": one per check the student is shown (audience.h) with "name" (the id),
///   "description" (what it checks), "points", "max_points", "message" (outcome and summary) and
///   "output" (check_findings.h).
///
/// PrairieLearn shows every test to the student and has no per-test visibility, so the checks a
/// student is not shown are summed into one test per stage, "stage N: hidden checks", with their
/// points and nothing of their names, inputs or output. Their points still count, the tests' points
/// add up to the score, and the student learns which stage lost them, as the per-stage partial
/// credit intends (docs/design, "Student code versus reference code").
///
/// No "images": the documentation limits the whole file to 1 MB, which a render check's three
/// images as data URLs can exceed on their own; the HTML report shows them. For the same limit,
/// each test's output is clipped to a share of about 800 KB.
nlohmann::json prairielearn_results(const GradeReport& report);

}  // namespace raystep::grade
