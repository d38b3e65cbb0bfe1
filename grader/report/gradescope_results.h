#pragma once

#include <nlohmann/json.hpp>

#include "app/report/grade_report.h"

namespace raystep::grade {

/// Gradescope's results.json for the grade, as its autograder specification has it
/// (https://gradescope-autograders.readthedocs.io/en/latest/specs/, "Output format"):
///
/// - "score", the total, and "execution_time", the grading's seconds;
/// - "output", the intake problem if there was one (GradeReport::intake_problem), then the stage
///   table of the checks every student sees (console_summary.h): Gradescope shows it to the
///   student at once, and hides the total while any test is not visible;
/// - "stdout_visibility": "hidden", since raystep-grade's console may be the instructor's view;
/// - "tests": one per check, in report order, with "score", "max_score", "status" ("passed" only
///   for the outcome passed, whatever the points), "name", "number" ("3.2": the stage, then the
///   check's place in it; 0 is the pipeline), "output" (outcome and summary, then
///   check_findings.h for the student, who reads it), "tags" (the stage and kind), "visibility"
///   (the rubric's, kept, so that Gradescope withholds hidden checks itself) and "extra_data"
///   (id, outcome and metrics).
///
/// Every string is plain text ("output_format", "name_format" and the defaults for tests are all
/// "text"): Gradescope renders "simple_format", its default for the top-level output, as HTML,
/// and a student's answers are never rendered.
nlohmann::json gradescope_results(const GradeReport& report);

}  // namespace raystep::grade
