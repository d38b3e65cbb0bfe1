#pragma once

#include <vector>

#include "stages/4_accel/bvh.h"
#include "studies/structures/bench_structure.h"

namespace raystep {

// Our structures as the bench measures them, through the stage-4 API of whichever stages this
// program was built with (a student's, or the solutions). This file and the command are the only
// bench code that calls stage code.

/// Bvh(list, split): "BVH SAH" or "BVH median".
BenchCandidate bvh_candidate(BvhSplit split);

/// UniformGrid(list): "grid".
BenchCandidate grid_candidate();

/// Stage 3's closest_hit over the whole list: "brute force". Subsampled, and only on scenes of at
/// most kBruteForceLimit primitives.
BenchCandidate brute_force_candidate();

/// Scenes larger than this skip brute force: the bunny (75,408 triangles) still gets it.
inline constexpr std::size_t kBruteForceLimit = 100000;

/// The report's rows in order: BVH SAH, BVH median, grid, brute force.
std::vector<BenchCandidate> our_structures();

}  // namespace raystep
