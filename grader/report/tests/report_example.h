#pragma once

#include <filesystem>
#include <string>

#include "app/report/grade_report.h"

namespace raystep::testing {

// A grade made by hand that exercises every report: every outcome, each visibility, render checks
// with images, and hostile text where a submission's output lands.

/// What a hostile submission prints: markup that would close a <pre> and run a script, quotes
/// that would end an attribute, `]]>` and `&`, a terminal escape and a carriage return, C0
/// controls, a bidirectional override, and bytes that are not UTF-8.
extern const std::string kHostile;

/// Marks in the hidden check's name, summary, input and details: no student's view may show them.
extern const std::string kHiddenSecret;

/// The pure magenta that the example's reference and student images are full of, so that a
/// screenshot of the HTML report can tell its images were drawn.
constexpr unsigned char kMarker[3] = {255, 0, 255};

/// The grade: checks in stages 1 to 7 and the pipeline, with every Outcome, a hidden, an
/// after-due-date and an after-published check (each with a counterexample whose input is marked
/// and hostile), two render checks whose images live under render/ (one with a space and a '#'
/// in a file name) and one whose image is missing. Every counterexample's `reproduce` is a
/// raystep-grade command; all but one have a `student_reproduce`. Each check has its own
/// seconds, a quarter second more than the one before it.
grade::GradeReport example_report();

/// The check with this id; throws std::out_of_range naming it when there is none.
const grade::CheckResult& find_check(const grade::GradeReport& report, const std::string& id);

/// Writes the render checks' images under `folder`, where the report's relative paths point.
void write_example_images(const std::filesystem::path& folder);

}  // namespace raystep::testing
