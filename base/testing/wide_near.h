#pragma once

#include <cmath>

#include "base/math/wide_vec.h"

namespace raystep::testing {

/// Whether each coordinate of a long-double answer lies within `tolerance` of the double one.
inline bool wide_near(const WideVec& got, const Vec3& expected, Wide tolerance = 1e-15L) {
    for (int k = 0; k < 3; ++k) {
        if (!(std::abs(got[k] - expected[k]) <= tolerance)) return false;
    }
    return true;
}

}  // namespace raystep::testing
