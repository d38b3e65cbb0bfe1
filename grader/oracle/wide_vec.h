#pragma once

#include <cmath>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "base/math/double_double_vec.h"
#include "base/math/types.h"

namespace raystep {

// The long-double arithmetic of the grader's high-precision oracles (stages 1, 2 and 4 to 11):
// 64-bit mantissas on x86-64, 11 more bits than a double, so that an expectation's own rounding
// is far below the tolerances a check allows. The oracles run only on the instructor's Linux
// machine; what they decide reaches the judges (app/grade/), which run on students' laptops too,
// as double-doubles (base/math/double_double.h), the same bits on every platform, or, where the
// tolerance is many ulps (stages 10 and 11), as the nearest double.
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

/// x as the judges take it: hi the nearest double, lo the rest rounded to double, which holds it
/// exactly (11 bits beyond hi's 53 on x86-64; any long double of up to 106 bits). A non-finite x
/// is its hi alone.
inline DoubleDouble double_double(Wide x) {
    const double hi = static_cast<double>(x);
    if (!std::isfinite(hi)) return DoubleDouble(hi);
    return {hi, static_cast<double>(x - hi)};
}

/// Each coordinate as double_double takes it.
inline DoubleDoubleVec3 double_double(const WideVec& v) {
    return {double_double(v.x), double_double(v.y), double_double(v.z)};
}

/// Each entry as double_double takes it.
inline DoubleDoubleMat4 double_double(const WideMat& w) {
    DoubleDoubleMat4 m;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            m[c][r] = double_double(w[c][r]);
    }
    return m;
}

}  // namespace raystep
