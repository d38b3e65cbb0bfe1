#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "base/math/types.h"

namespace raystep {

// The long-double arithmetic of the grader's high-precision oracles (stages 1, 2 and 5 to 7):
// 64-bit mantissas on x86-64, 11 more bits than a double, so that an expectation's own rounding
// is far below the tolerances a check allows.
using Wide = long double;
using WideVec = glm::vec<3, Wide>;
using WideMat = glm::mat<4, 4, Wide>;

/// The unit roundoff of a double (2^-53) as a long double, for tolerances summed in long double.
inline constexpr Wide kWideUnitRoundoff = 0x1p-53L;

/// pi to the digits a long double keeps.
inline constexpr Wide kWidePi = 3.141592653589793238462643383279502884L;

/// A double vector, exactly.
inline WideVec widen(const Vec3& v) {
    return {v.x, v.y, v.z};
}

/// The nearest double vector, each coordinate rounded once.
inline Vec3 narrow(const WideVec& v) {
    return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}

/// A double matrix, exactly.
inline WideMat widen(const Mat4& m) {
    WideMat w;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            w[c][r] = m[c][r];
    }
    return w;
}

/// The nearest double matrix, each entry rounded once.
inline Mat4 narrow(const WideMat& w) {
    Mat4 m;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            m[c][r] = static_cast<double>(w[c][r]);
    }
    return m;
}

}  // namespace raystep
