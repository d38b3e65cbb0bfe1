#include "app/grade/value_text.h"

#include <cmath>
#include <cstdio>

namespace raystep::grade {

std::string full_text(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

std::string full_text(const DoubleDouble& x) {
    return full_text(x.hi);
}

std::string full_text(const Vec2& v) {
    return "(" + full_text(v.x) + ", " + full_text(v.y) + ")";
}

std::string full_text(const Vec3& v) {
    return "(" + full_text(v.x) + ", " + full_text(v.y) + ", " + full_text(v.z) + ")";
}

std::string matrix_text(const Mat4& m) {
    std::string text;
    for (int r = 0; r < 4; ++r) {
        text += r == 0 ? "rows [" : "; [";
        for (int c = 0; c < 4; ++c)
            text += (c == 0 ? "" : ", ") + full_text(m[c][r]);
        text += "]";
    }
    return text;
}

std::string ray_text(const Ray& r) {
    return "origin " + full_text(r.origin) + ", direction " + full_text(r.direction) + ", t in [" +
           full_text(r.t_min) + ", " + full_text(r.t_max) + "]";
}

bool unit_length(const Vec3& v) {
    const DoubleDouble kUnitLength(4 * 0x1p-52);
    return abs(length(DoubleDoubleVec3(v)) - DoubleDouble(1.0)) <= kUnitLength;
}

bool near_wide(double got, const DoubleDouble& expected, const DoubleDouble& tolerance) {
    return abs(DoubleDouble(got) - expected) <= tolerance;
}

bool near_wide(const Vec3& got, const DoubleDoubleVec3& expected,
               const DoubleDoubleVec3& tolerance) {
    for (int k = 0; k < 3; ++k) {
        if (!near_wide(got[k], expected[k], tolerance[k])) return false;
    }
    return true;
}

bool near_double(double got, double expected, double tolerance) {
    return std::abs(got - expected) <= tolerance;
}

bool near_double(const Vec2& got, const Vec2& expected, double tolerance) {
    return near_double(got.x, expected.x, tolerance) && near_double(got.y, expected.y, tolerance);
}

bool near_double(const Vec3& got, const Vec3& expected, double tolerance) {
    return near_double(got.x, expected.x, tolerance) && near_double(got.y, expected.y, tolerance) &&
           near_double(got.z, expected.z, tolerance);
}

}  // namespace raystep::grade
