// Stage 8: sample patterns over the unit square. Handout: docs/stage8.md.

#include <cmath>
#include <stdexcept>
#include <string>

#include "stages/8_sampling/sampling.h"

namespace raystep {

namespace {

void check_strata(int strata_per_side) {
    if (strata_per_side < 1) {
        throw std::domain_error("samples: " + std::to_string(strata_per_side) +
                                " strata per side; at least 1 is needed");
    }
}

// n when count = n^2; throws otherwise, naming the pattern that needs a square.
int side_of_square(int count, const char* pattern) {
    const int n = static_cast<int>(std::lround(std::sqrt(static_cast<double>(count))));
    if (count < 1 || n * n != count) {
        throw std::domain_error(std::string("samples: ") + pattern + " sampling needs a square " +
                                "number of samples (n x n strata), not " + std::to_string(count));
    }
    return n;
}

// A coordinate of stratum [a/n, (a+1)/n), given the far edge (a+1)/n: (a + u) / n is below it in
// exact arithmetic, but not always in doubles. With u within a few ulps of 1, a + u rounds up to
// a + 1 (1 + (1 - 2^-53) is a tie, and ties go to the even 2), and the division can round up onto
// the edge: the point lands in the next stratum, or on 1 outside the square. Such a point moves
// to the last double below the edge.
double inside_stratum(double coordinate, double far_edge) {
    return coordinate < far_edge ? coordinate : std::nextafter(far_edge, 0.0);
}

}  // namespace

std::vector<Vec2> jittered_samples(int strata_per_side, RandomStream& random) {
    check_strata(strata_per_side);
    const int n = strata_per_side;
    std::vector<Vec2> points;
    points.reserve(static_cast<std::size_t>(n) * n);
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) {
            const Vec2 u = random.next2();
            points.push_back({inside_stratum((a + u.x) / n, (a + 1.0) / n),
                              inside_stratum((b + u.y) / n, (b + 1.0) / n)});
        }
    }
    return points;
}

std::vector<Vec2> regular_samples(int strata_per_side) {
    check_strata(strata_per_side);
    const int n = strata_per_side;
    std::vector<Vec2> points;
    points.reserve(static_cast<std::size_t>(n) * n);
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a)
            points.push_back({(a + 0.5) / n, (b + 0.5) / n});
    }
    return points;
}

std::vector<Vec2> random_samples(int count, RandomStream& random) {
    if (count < 1) {
        throw std::domain_error("random_samples: " + std::to_string(count) +
                                " samples; at least 1 is needed");
    }
    std::vector<Vec2> points;
    points.reserve(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k)
        points.push_back(random.next2());
    return points;
}

std::vector<Vec2> samples(SamplePattern pattern, int count, RandomStream& random) {
    switch (pattern) {
        case SamplePattern::jittered:
            return jittered_samples(side_of_square(count, "jittered"), random);
        case SamplePattern::regular:
            return regular_samples(side_of_square(count, "regular"));
        case SamplePattern::random:
            return random_samples(count, random);
    }
    throw std::domain_error("samples: unknown pattern");
}

}  // namespace raystep
