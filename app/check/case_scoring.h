#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/check/case_answer.h"
#include "app/check/ray_case.h"
#include "app/check/stage3_methods.h"

namespace raystep {

// Scoring: the trusted half of a check. Compares a method's answers with the exact oracle's
// expectations, case by case, and sums them up per family.

/// How one case went. The first failing rule, in this order, decides.
enum class Verdict {
    pass,
    not_finite,  ///< a reported hit with a NaN or infinite t, normal or barycentric
    false_hit,   ///< a hit where the exact answer is a miss, away from any boundary
    false_miss,  ///< a miss where the exact answer is a hit, away from any boundary
    leak,     ///< watertight case: the exact ray meets the group, and no primitive reported a hit
    wrong_t,  ///< a hit whose t is off by more than the expectation's t_tolerance
    wrong_normal,  ///< a hit whose normal is not within normal_tolerance of the exact unit normal,
                   ///< or whose length is off 1 by more than that (and 1e-9)
    wrong_barycentrics,  ///< a triangle hit whose beta or gamma is off by more than the tolerance
    wrong_primitive,     ///< closest_hit chose a primitive that is not the nearest hit
    threw,               ///< the method threw something other than NotImplemented
};
constexpr int kVerdictCount = 10;

/// A case a method got wrong, with what is needed to rerun it.
struct Counterexample {
    std::uint64_t case_index = 0;
    Verdict verdict = Verdict::pass;
    std::string detail;  ///< which primitive, expected against got, in words
    std::string text;    ///< the case as the case file shows it (case_text)
};

/// One method over one family.
struct MethodScore {
    std::string method;
    std::string family;
    std::size_t cases = 0;  ///< cases with at least one primitive the method applies to
    std::size_t passed = 0;
    std::array<std::size_t, kVerdictCount> counts{};  ///< cases per Verdict, by its int value
    std::size_t near_boundary_hits = 0;    ///< informational: hits reported where either passes
    std::size_t near_boundary_misses = 0;  ///< informational: misses reported where either passes
    /// Against the exact answers alone, near a boundary or not: cases where the method reported
    /// a hit and the ray misses every primitive it tests exactly, and cases where it reported none
    /// and the ray hits one exactly (a leak included). What the speed-against-error study counts,
    /// whatever the verdict; which neighbour of a shared edge takes the ray is not counted.
    std::size_t exact_false_hits = 0;
    std::size_t exact_false_misses = 0;
    /// For every primitive whose exact answer is a hit (near a boundary or not) and which the
    /// method also reported hit: |t - expected t| in units in the last place.
    /// Hits whose exact t lies within its tolerance of 0 (a ray that starts on the surface, or a
    /// sliver whose tolerance is wider than its t) are counted apart, with their largest
    /// |t - expected t|: an ulp of a t that small is so small that a right answer can sit 1e15 of
    /// them away, and would look like a failure in t_ulps.
    std::vector<double> t_ulps;
    std::size_t hits_at_t_zero = 0;
    double largest_t_error_at_zero = 0.0;
    bool not_implemented = false;  ///< the method is still a stub: nothing was scored
    std::string not_implemented_message;
    std::vector<Counterexample> counterexamples;  ///< the first few failures, in case order

    std::size_t count(Verdict verdict) const { return counts[static_cast<int>(verdict)]; }
};

/// The distance between two doubles in units in the last place: how many doubles lie between
/// them, plus one; 0 when equal; infinity when either is NaN.
double ulp_distance(double a, double b);

/// The verdict for one case, and the reason in words when it is not a pass.
Verdict score_case(const Stage3Method& method, const RayCase& ray_case, const CaseAnswer& answer,
                   std::string& detail);

/// Scores a method's answers (one per case, in family order) over the family. Stops at the first
/// NotImplemented answer: a stub makes the whole method "not implemented".
MethodScore score_family(const Stage3Method& method, const CaseFamily& family,
                         const std::vector<CaseAnswer>& answers,
                         std::size_t keep_counterexamples = 3);

/// The verdict's name in reports: "false miss", "wrong t", ...
const char* verdict_name(Verdict verdict);

}  // namespace raystep
