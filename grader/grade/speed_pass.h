#pragma once

#include "app/report/grade_report.h"

namespace raystep::grade {

// A batch grades a class in two passes (batch.h): every check but speed, several submissions at a
// time, then the speed checks, one submission at a time on an otherwise idle machine. These put a
// submission's two reports together.

/// Whether `report` lacks a speed check the grader has: the first pass wrote it, and the second
/// has yet to run (or was stopped before it did).
bool lacks_speed_checks(const GradeReport& report);

/// `first` with the checks of `speed` (the second pass's report of the same submission) put in,
/// every check in the order all_checks() lists it, and the second pass's intake, build and check
/// times added to the first's.
GradeReport with_speed_checks(GradeReport first, const GradeReport& speed);

}  // namespace raystep::grade
