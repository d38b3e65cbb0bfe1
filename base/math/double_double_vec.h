#pragma once

#include <array>

#include "base/math/double_double.h"
#include "base/math/types.h"

namespace raystep {

// Vectors and matrices of double-doubles (double_double.h says why double-doubles): how the
// judges (app/grade/, grading/*/) hold an expectation decided with more bits than a double, and the
// little they and their tests compute on one (differences, dot and cross products, lengths). Not
// glm's templates: glm's functions accept only the built-in floating-point types.

/// Three double-doubles, x, y, z.
struct DoubleDoubleVec3 {
    DoubleDouble x;
    DoubleDouble y;
    DoubleDouble z;

    DoubleDoubleVec3() = default;
    DoubleDoubleVec3(const DoubleDouble& vx, const DoubleDouble& vy, const DoubleDouble& vz)
        : x(vx), y(vy), z(vz) {}
    /// Three doubles, exactly.
    DoubleDoubleVec3(double vx, double vy, double vz) : x(vx), y(vy), z(vz) {}
    /// A double vector, exactly.
    explicit DoubleDoubleVec3(const Vec3& v) : DoubleDoubleVec3(v.x, v.y, v.z) {}
    /// Every coordinate `all` (a per-coordinate tolerance).
    explicit DoubleDoubleVec3(const DoubleDouble& all) : x(all), y(all), z(all) {}
    explicit DoubleDoubleVec3(double all) : DoubleDoubleVec3(DoubleDouble(all)) {}

    /// Coordinate k: x, y, z for 0, 1, 2.
    const DoubleDouble& operator[](int k) const { return k == 0 ? x : k == 1 ? y : z; }
    DoubleDouble& operator[](int k) { return k == 0 ? x : k == 1 ? y : z; }
};

/// The nearest double vector, each coordinate rounded once.
inline Vec3 narrow(const DoubleDoubleVec3& v) {
    return {v.x.hi, v.y.hi, v.z.hi};
}

inline DoubleDoubleVec3 operator+(const DoubleDoubleVec3& a, const DoubleDoubleVec3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}

inline DoubleDoubleVec3 operator-(const DoubleDoubleVec3& a, const DoubleDoubleVec3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}

inline DoubleDoubleVec3 operator*(const DoubleDouble& s, const DoubleDoubleVec3& v) {
    return {s * v.x, s * v.y, s * v.z};
}

inline DoubleDouble dot(const DoubleDoubleVec3& a, const DoubleDoubleVec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

inline DoubleDoubleVec3 cross(const DoubleDoubleVec3& a, const DoubleDoubleVec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

inline DoubleDouble length(const DoubleDoubleVec3& v) {
    return sqrt(dot(v, v));
}

/// A 4x4 matrix of double-doubles, indexed [column][row] as glm's are; all zeros unless built from
/// a double matrix.
struct DoubleDoubleMat4 {
    std::array<std::array<DoubleDouble, 4>, 4> columns{};

    DoubleDoubleMat4() = default;
    /// A double matrix, exactly.
    explicit DoubleDoubleMat4(const Mat4& m) {
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r)
                columns[c][r] = DoubleDouble(m[c][r]);
        }
    }

    const std::array<DoubleDouble, 4>& operator[](int c) const { return columns[c]; }
    std::array<DoubleDouble, 4>& operator[](int c) { return columns[c]; }
};

/// The nearest double matrix, each entry rounded once.
inline Mat4 narrow(const DoubleDoubleMat4& w) {
    Mat4 m;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            m[c][r] = w[c][r].hi;
    }
    return m;
}

}  // namespace raystep
