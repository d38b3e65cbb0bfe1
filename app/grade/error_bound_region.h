#pragma once

#include <string>

#include "base/math/double_double_vec.h"
#include "base/math/types.h"

namespace raystep::grade {

// Where the error-bound rule of spawn_ray (stages/6_shading/shading.h) promises a leaving ray's
// origin to be. The grader's oracle decides the region with more bits than a double
// (grader/oracle/error_bound_origin.h); a data judge holds it as data (shading_judges.h, every bit
// kept) and tests an origin against it here in double-double, so that the grader and a student
// release judge the same origin alike, bit for bit. No JSON here: the oracle's own library includes
// this header.

/// With n the leaving side's unit normal and d = sum |n_i| error_i: strictly more than d along n
/// from the point, no more than `ulps` beyond d, and within `ulps` of the line along n.
struct ErrorBoundOrigin {
    DoubleDoubleVec3 point;
    DoubleDoubleVec3 normal;
    DoubleDouble offset;
    double ulps;
};

/// Whether `origin` is in the region. The origin and the point differ by a few ulps and d, so
/// their difference is exact in double-double and its dot product with n rounds some 2^-104 of d,
/// far below the half ulp the rule's step adds. Written so that a NaN fails.
bool within(const ErrorBoundOrigin& region, const Vec3& origin);

/// "origin more than d and at most d + ulps along n from the point p, within ulps of that line",
/// as a report writes the region.
std::string region_text(const ErrorBoundOrigin& region);

}  // namespace raystep::grade
