#pragma once

// The tolerances of the oracle, all from one budget: each input coordinate may move by
// kRoundingUlps units of double rounding (2^-53) of the problem's largest coordinate, and each
// direction by as much relative to its length. docs/case-files.md, "Where the tolerances come
// from", derives each formula.

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "base/math/types.h"
#include "grading/3_intersect/exact_intersection.h"

namespace raystep {

/// How far a correct double-precision test may be off, relative to a length.
inline constexpr double kRelativeSlack = kRoundingUlps * 0x1p-53;

/// The largest |coordinate| among the points.
inline double largest_coordinate(std::initializer_list<Vec3> points) {
    double largest = 0.0;
    for (const Vec3& p : points) {
        largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    return largest;
}

/// How far a position may move: the slack of the problem's magnitude.
inline double position_slack(double magnitude) {
    return kRelativeSlack * magnitude;
}

}  // namespace raystep
