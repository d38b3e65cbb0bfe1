#pragma once

#include <cmath>

#include "grader/oracle/wide_vec.h"

namespace raystep::testing {

/// Whether each coordinate of a long-double answer lies within `tolerance` of the double one.
inline bool wide_near(const WideVec& got, const Vec3& expected, Wide tolerance = 1e-15L) {
    for (int k = 0; k < 3; ++k) {
        if (!(std::abs(got[k] - expected[k]) <= tolerance)) return false;
    }
    return true;
}

/// The same for an expectation the judges hold (a double-double), compared in double-double.
inline bool wide_near(const DoubleDoubleVec3& got, const Vec3& expected, double tolerance = 1e-15) {
    for (int k = 0; k < 3; ++k) {
        if (!(abs(got[k] - DoubleDouble(expected[k])) <= DoubleDouble(tolerance))) return false;
    }
    return true;
}

}  // namespace raystep::testing
