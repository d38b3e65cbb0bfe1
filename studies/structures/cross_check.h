#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "studies/structures/bench_structure.h"
#include "studies/structures/measurement.h"

namespace raystep {

/// Where two structures' answers on a ray set differ, over the rays both ran.
struct AnswerComparison {
    std::size_t compared = 0;   ///< rays both ran
    std::size_t differing = 0;  ///< of those, the rays with another primitive or another t
    std::size_t first_ray = 0;  ///< the first differing ray's index in the ray set
    BenchHit first_a;           ///< a's answer there
    BenchHit first_b;           ///< b's answer there
};

/// Compares answers `a` and `b`, where a[k] answers ray k stride_a of a ray set and b[k] ray
/// k stride_b, on the rays both ran.
AnswerComparison compare_answers(const std::vector<BenchHit>& a, std::size_t stride_a,
                                 const std::vector<BenchHit>& b, std::size_t stride_b);

/// The cross-check of one ray set: every measured structure that is not a baseline (Embree works
/// in float, so its hits differ by design) against the first one, which must return the same hits
/// by stage 4's contract. One line when all agree; otherwise a WARNING line per structure that
/// differs, with its first differing ray, since that means a bug in one of the two. Empty when
/// fewer than two structures ran.
std::vector<std::string> cross_check_lines(const std::vector<StructureMeasurement>& measurements,
                                           std::size_t ray_set);

}  // namespace raystep
