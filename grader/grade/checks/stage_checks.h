#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "app/check/ray_case.h"
#include "app/check/stage3_methods.h"
#include "app/grade/public_case.h"
#include "grader/grade/check_definition.h"

namespace raystep::grade {

// The checks of each stage, in grader/grade/checks/. all_checks() puts them together.

std::vector<CheckDefinition> stage1_checks();
std::vector<CheckDefinition> stage2_checks();
std::vector<CheckDefinition> stage3_checks();
std::vector<CheckDefinition> stage4_checks();
std::vector<CheckDefinition> stage5_checks();
std::vector<CheckDefinition> stage6_checks();
std::vector<CheckDefinition> stage7_checks();
/// Stage 8's deterministic checks, "stage8.unit", "stage8.hidden" and "stage8.oracle", then its
/// statistical ones and its noisy render checks.
std::vector<CheckDefinition> stage8_checks();
/// Stage 8's checks of its random answers by their distributions, each with a stated false-fail
/// rate, seeded by statistics_seed() (stage8_statistics.cpp).
std::vector<CheckDefinition> stage8_statistical_checks();
/// The render checks of sampled scenes, each view rendered at several seeds and compared tile by
/// tile with the reference's mean (noisy_render_checks.cpp).
std::vector<CheckDefinition> noisy_render_checks();
/// Stage 9's checks, "stage9.unit", "stage9.hidden" and "stage9.oracle", then three contract
/// edges of their own, "stage9.hidden.latest_entry", "shading_normal" and "cosine_above_one"
/// (stage9_checks.cpp).
std::vector<CheckDefinition> stage9_checks();
/// Stage 10's checks, "stage10.unit", "stage10.hidden" and "stage10.oracle" (stage10_checks.cpp),
/// then its statistical ones.
std::vector<CheckDefinition> stage10_checks();
/// Stage 10's checks by distribution and by mean, each with a stated false-fail rate, seeded by
/// statistics_seed() (stage10_statistics.cpp).
std::vector<CheckDefinition> stage10_statistical_checks();
/// Stage 11's checks, "stage11.unit", "stage11.hidden" and an oracle check for each part of the
/// contract, "stage11.oracle.interpolation" and the rest (stage11_checks.cpp);
/// its maps are render checks (render_checks.cpp).
std::vector<CheckDefinition> stage11_checks();
std::vector<CheckDefinition> render_checks();

/// The render checks render at most this wide: enough to see a stage's mistakes, small enough
/// that a slow submission still renders every check within its time.
inline constexpr int kRenderCheckWidth = 160;

/// The public checks of each stage as data (grader/grade/checks/data_judged.h): what the stage's
/// "stageN.unit" check runs, and what the student release's `raystep grade` runs.
PublicCheck stage1_public_check();
PublicCheck stage2_public_check();
/// Stage 4's two unit checks, "stage4.unit.slab" and "stage4.unit.grid_resolution".
PublicCheck stage4_slab_public_check();
PublicCheck stage4_grid_resolution_public_check();
PublicCheck stage5_public_check();
PublicCheck stage6_public_check();
PublicCheck stage7_public_check();
PublicCheck stage8_public_check();
PublicCheck stage9_public_check();
PublicCheck stage10_public_check();
PublicCheck stage11_public_check();

/// A sample of each stage's generated cases for the student release (kSampleKind,
/// app/grade/public_case.h): a few of each kind the "stageN.oracle" check draws, decided by the
/// same oracle, from its seeds plus kSampleSeedOffset (sample_check, data_judged.h).
PublicCheck stage1_sample_check();
PublicCheck stage2_sample_check();
/// Stage 4's: structure queries judged against brute force's closest hit, without the work count
/// the grader's "stage4.oracle" checks add (a release cannot count primitive tests).
PublicCheck stage4_sample_check();
PublicCheck stage5_sample_check();
PublicCheck stage6_sample_check();
PublicCheck stage7_sample_check();
PublicCheck stage8_sample_check();
PublicCheck stage9_sample_check();
PublicCheck stage10_sample_check();
PublicCheck stage11_sample_check();

/// The render checks as data, each with the reference's render at the grader's size, made from
/// the scenes under `source`/scenes: the grader judges a render by the same rule
/// (app/compare/render_rule.h) against the same image, rendered the same way.
std::vector<PublicCheck> render_public_checks(const std::filesystem::path& source);

/// One stage-3 case for one function of intersect.h (stage3_checks.cpp): the probe runs the
/// function on the case alone, and the judge scores the answer as `raystep check` does, a stub's
/// answer as not implemented. A leak passes and adds one to `leaks`, which must outlive the case.
/// The student's reproduce line is the case as a case file of its own and the `raystep check`
/// command that runs it.
ProbeCase method_case(const Stage3Method& method, const CaseFamily& family, const RayCase& ray_case,
                      std::size_t& leaks);

/// method_case for each method on each case of each family that has a primitive it tests, methods
/// outermost: one query per case, so that every case is in the denominator and has a number of
/// its own to reproduce it by.
std::vector<ProbeCase> method_cases(const std::vector<Stage3Method>& methods,
                                    const std::vector<CaseFamily>& families, std::size_t& leaks);

/// Stage 3's contract edges, each a check of its own (stage3_contract_checks.cpp):
/// "stage3.contract.range_ends", ".ties", ".ray_in_plane" and ".degenerate".
std::vector<CheckDefinition> stage3_contract_checks();

/// Stage 3's intersect_triangle, its speed against its error on one family
/// (stage3_speed_error.cpp), and the names of what it measures, which the report's chart reads
/// back (grader/grade/speed_error_chart.h).
CheckDefinition stage3_speed_error_check();
inline constexpr const char* kSpeedErrorCheck = "stage3.speed.intersect_triangle";
inline constexpr const char* kSpeedErrorFamily = "shared-edges";
inline constexpr const char* kSpeedErrorCases = "cases";
inline constexpr const char* kSpeedErrorFalseHits = "false hits";
inline constexpr const char* kSpeedErrorFalseMisses = "false misses (leaks included)";
inline constexpr const char* kSpeedErrorUlpsMedian = "t ulps, median";
inline constexpr const char* kSpeedErrorUlpsP99 = "t ulps, 99th percentile";
inline constexpr const char* kSpeedErrorAgainstCramer = "speed against the reference's Cramer";

}  // namespace raystep::grade
