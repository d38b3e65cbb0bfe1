// Stage 1 reference solution.

#include "stages/1_vectors/vectors.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/math/to_text.h"

namespace raystep {

namespace {

double largest_magnitude(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

double dot(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

double length(const Vec3& v) {
    if (!is_finite(v)) return std::abs(v.x) + std::abs(v.y) + std::abs(v.z);  // inf or NaN
    // Scale into [-1, 1] first: the squares of 1e200 overflow and those of 1e-200 underflow,
    // though the length itself is a perfectly good double. The division costs one rounding.
    const double m = largest_magnitude(v);
    if (m == 0.0) return 0.0;
    const Vec3 s = v / m;
    return m * std::sqrt(dot(s, s));
}

Vec3 normalize(const Vec3& v) {
    const double m = largest_magnitude(v);
    if (!is_finite(v) || m == 0.0) {
        throw std::domain_error("normalize: " + to_text(v) + " has no direction");
    }
    const Vec3 s = v / m;  // as in length(): no overflow, no underflow
    return s / std::sqrt(dot(s, s));
}

Vec3 reflect(const Vec3& d, const Vec3& n) {
    return d - 2.0 * dot(d, n) * n;
}

Vec3 project_onto(const Vec3& v, const Vec3& onto) {
    if (largest_magnitude(onto) == 0.0) {
        throw std::domain_error("project_onto: cannot project onto the zero vector");
    }
    // Through the unit vector rather than (v . o) / (o . o), whose o . o overflows for |o| > 1e154.
    const Vec3 unit = normalize(onto);
    return dot(v, unit) * unit;
}

Vec3 perpendicular_to(const Vec3& v, const Vec3& edge) {
    return v - project_onto(v, edge);
}

Frame orthonormal_frame(const Vec3& a, const Vec3& b) {
    if (largest_magnitude(a) == 0.0) throw std::domain_error("orthonormal_frame: a is zero");
    if (largest_magnitude(b) == 0.0) throw std::domain_error("orthonormal_frame: b is zero");
    const Vec3 w = normalize(a);
    const Vec3 b_cross_w = cross(b, w);
    // Not "== 0": w is rounded, so b x w of a b parallel to a is a few ulps, not zero.
    if (length(b_cross_w) <= kParallelSine * length(b)) {
        throw std::domain_error("orthonormal_frame: b " + to_text(b) + " is parallel to a " +
                                to_text(a));
    }
    const Vec3 u = normalize(b_cross_w);
    return {u, cross(w, u), w};
}

}  // namespace raystep
