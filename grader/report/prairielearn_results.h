#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "app/report/grade_report.h"

namespace raystep::grade {

/// PrairieLearn's external grader results.json for the grade, as its documentation has it
/// (https://prairielearn.readthedocs.io/en/latest/externalGrading/, "Grading results"):
///
/// - "gradable": false only when the report has checks and none of them compiled: PrairieLearn
///   then awards and takes no points and gives the attempt back, as its documentation intends
///   for a syntax error, with the intake problem if there was one and the compilers' first lines
///   in "format_errors". A stage that does not compile beside stages that do is graded: it scores
///   zero and the others keep their points.
/// - "score": the total over the maximum, in [0, 1]; 0 when there is nothing to score.
/// - "message": the intake problem if there was one (GradeReport::intake_problem), then the
///   points in words; "output": the stage table (console_summary.h).
/// - "tests": one per check the student is shown (audience.h) with "name" (the id),
///   "description" (what it checks), "points", "max_points", "message" (outcome and summary),
///   "output" (check_findings.h for the student, who reads it) and, for a render check, "images":
///   its reference, student and difference images as {"label", "url"} with data URLs, read from
///   `images_folder`, where the report's image paths are relative to.
///
/// PrairieLearn shows every test to the student and has no per-test visibility, so the checks a
/// student is not shown are summed into one test per stage, "stage N: hidden checks", with their
/// points and nothing of their names, inputs, output or images. Their points still count, the
/// tests' points add up to the score, and the student learns which stage lost them, as the
/// per-stage partial credit intends (ARCHITECTURE.md, "Student code or the reference").
///
/// The documentation limits the whole file to 1 MB: the tests' outputs share about 400 KB, each
/// clipped to its share, and the images about 450 KB, given first to the checks that did not
/// pass; a check whose images do not fit has none, and its output says so.
nlohmann::json prairielearn_results(const GradeReport& report,
                                    const std::filesystem::path& images_folder);

}  // namespace raystep::grade
