// Stage 8: sample patterns over the unit square. Handout: docs/stage8.md. Draw every random
// number from `random` (random.next() in [0, 1), random.next2() a point of [0, 1)^2), never from
// std::rand or a generator of your own: the renderer and the grader hand you the stream.

#include "base/errors/not_implemented.h"
#include "stages/8_sampling/sampling.h"

namespace raystep {

std::vector<Vec2> jittered_samples(int strata_per_side, RandomStream& random) {
    // For each stratum (a, b) of the n x n grid, one point ((a + u.x) / n, (b + u.y) / n) with
    // u = random.next2(): every stratum gets exactly one sample, placed at random inside it.
    // Keep it below the stratum's far edge (a + 1) / n: in doubles, a u within an ulp of 1 makes
    // a + u round up to a + 1.
    RAYSTEP_TODO(8, "jittered_samples", "Jittered samples");
}

std::vector<Vec2> regular_samples(int strata_per_side) {
    // The centres ((a + 0.5) / n, (b + 0.5) / n) of the same strata.
    RAYSTEP_TODO(8, "regular_samples", "Jittered samples");
}

std::vector<Vec2> random_samples(int count, RandomStream& random) {
    // `count` points random.next2(), nothing else.
    RAYSTEP_TODO(8, "random_samples", "Jittered samples");
}

std::vector<Vec2> samples(SamplePattern pattern, int count, RandomStream& random) {
    // Jittered and regular: n x n strata with n^2 = count (throw std::domain_error when count is
    // not a square); random: count points.
    RAYSTEP_TODO(8, "samples", "Jittered samples");
}

}  // namespace raystep
