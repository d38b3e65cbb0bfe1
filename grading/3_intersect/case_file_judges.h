#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "app/check/ray_case.h"
#include "app/check/stage3_methods.h"
#include "app/grade/rubric.h"
#include "app/report/grade_report.h"

namespace raystep::grade {

// Stage 3's public checks: each function of intersect.h over the public case files
// (stages/3_intersect/cases/, decided by the exact oracle), scored as `raystep check` scores them
// (app/check/case_scoring.h), one check per function, "stage3.cases.FUNCTION". Each is worth
// points of its own, so that one right function shows in `raystep grade` before the others are
// written; the grader runs the same check through the probe (grading/3_intersect/stage3_checks.cpp)
// and scores it by the same fraction.
//
// The public files hold a harder mix than the grader's generated cases, on which even the
// reference's projection, half-space and Cramer tests miss some near-boundary cases. So the
// measure is the reference's count: a function earns full marks when it gets at least as many
// cases right as the reference does (the count the release writer takes from the reference,
// stage3_cases_right, and writes beside the case files). A leak at a shared edge counts as right,
// as the grader's stage-3 checks count it: the lecture methods leak by design, and a right Cramer
// must pass where the reference's watertight intersect_triangle does.

/// Every family of the public case files of the tree at `root` (stages/3_intersect/cases/), in
/// file order: what `raystep grade`, the release writer and the grader's stage3.cases checks read.
std::vector<CaseFamily> stage3_public_families(const std::filesystem::path& root);

/// How many cases of the families each function of this build gets right, by function name; for
/// intersect_triangle, which may be any of the three methods, the lowest count of the four. A
/// stub's function is left out.
std::map<std::string, std::size_t> stage3_cases_right(const std::vector<CaseFamily>& families);

/// What a case asks of a function: a hit (a primitive it tests is hit, away from every decision
/// boundary), a miss (every one it tests missed, away from them), or either (near a boundary,
/// where a right test may answer both ways, or no primitive it tests).
enum class CaseKind { hit, miss, either };

CaseKind case_kind(const Stage3Method& method, const RayCase& ray_case);

/// A function's case check earns nothing unless it gets at least this share right of the cases
/// that must hit and of those that must miss. Most cases are misses or near a boundary, where
/// either answer passes (86% of a triangle test's among the grader's families), so a constant
/// answer, a stub that returns nothing, would otherwise earn most of its share. Not the lesser of
/// the two shares itself: a right projection test misses a few of the hard families' hits by
/// rounding (5 of 55 in the model), which the rubric forgives on the share of all cases.
inline constexpr double kLeastShareOfEachKind = 0.5;

/// A function's answers counted by what each case asks.
struct KindTally {
    std::size_t hits = 0;
    std::size_t hits_right = 0;
    std::size_t misses = 0;
    std::size_t misses_right = 0;

    void count(CaseKind kind, bool right);
    /// At least kLeastShareOfEachKind of each kind right, or a kind not asked.
    bool both_kinds_kept() const;
    /// "earns nothing: 0 of the 55 cases that must hit right, ...", for a summary.
    std::string shortfall() const;
};

/// What the rubric scores of a function that got `right` cases right where the reference got
/// `reference_right`: their ratio, at most 1 (a function may beat the reference on a
/// near-boundary case). 1 when the reference gets none right.
double stage3_cases_fraction(std::size_t right, std::size_t reference_right);

/// The checks, for every function of intersect.h, scored by `rubric`; `reference` holds the
/// reference's counts (stage3_cases_right of the reference). A stub is not implemented; the first
/// failing case of a function is its counterexample, with the `raystep check` command that reruns
/// it. Throws std::out_of_range when `reference` or `rubric` has no entry for a function.
std::vector<CheckResult> run_stage3_case_checks(const std::vector<CaseFamily>& families,
                                                const std::map<std::string, std::size_t>& reference,
                                                const Rubric& rubric);

}  // namespace raystep::grade
