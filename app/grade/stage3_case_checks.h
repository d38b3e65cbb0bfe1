#pragma once

#include <map>
#include <string>
#include <vector>

#include "app/check/ray_case.h"
#include "app/report/grade_report.h"

namespace raystep::grade {

// Stage 3's public checks in `raystep grade`: each function of intersect.h over the public case
// files (stages/3_intersect/cases/, decided by the exact oracle), scored as `raystep check` scores
// them (app/check/case_scoring.h), one check per function, "stage3.cases.FUNCTION".
//
// They earn no points: the grader scores each function on its own generated cases
// ("stage3.oracle.FUNCTION", not run here), and the public files hold a harder mix, on which even
// the reference's projection, half-space and Cramer tests miss some near-boundary cases. So a
// check passes when the function gets at least as many cases right as the reference does, a
// count the release writer takes from the reference (stage3_cases_right) and writes beside the
// case files. A leak at a shared edge counts as right, as the grader's stage-3 checks count it:
// the lecture methods leak by design, and a right Cramer must pass where the reference's
// watertight intersect_triangle does.

/// How many cases of the families each function of this build gets right, by function name.
/// A stub's function is left out.
std::map<std::string, std::size_t> stage3_cases_right(const std::vector<CaseFamily>& families);

/// The checks, for every function of intersect.h; `reference` holds the reference's counts
/// (stage3_cases_right of the reference). A stub is not implemented; the first failing case of a
/// function is its counterexample, with the `raystep check` command that reruns it. Throws
/// std::out_of_range when `reference` has no count for a function.
std::vector<CheckResult> run_stage3_case_checks(
    const std::vector<CaseFamily>& families, const std::map<std::string, std::size_t>& reference);

}  // namespace raystep::grade
