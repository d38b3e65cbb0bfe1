// Stage 1: vector math. Handout: docs/stage1.md.

#include "stages/1_vectors/vectors.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace raystep {

namespace {

// The largest |component|: lengths are measured in units of it, so that no square overflows
// (components near 1e200) or underflows (near 1e-200).
double largest_component(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

bool all_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

double dot(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

Vec3 cross(const Vec3& a, const Vec3& b) {
    return Vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

double length(const Vec3& v) {
    // |v| = m |v / m| with m the largest |component|: v / m has components in [-1, 1].
    const double m = largest_component(v);
    if (m == 0.0) return 0.0;
    if (!std::isfinite(m)) return m;  // infinite or NaN
    const Vec3 scaled = v / m;
    return m * std::sqrt(dot(scaled, scaled));
}

Vec3 normalize(const Vec3& v) {
    const double m = largest_component(v);
    if (!all_finite(v) || m == 0.0) {
        throw std::domain_error("normalize: the vector is zero or not finite, it has no direction");
    }
    const Vec3 scaled = v / m;
    return scaled / std::sqrt(dot(scaled, scaled));
}

Vec3 reflect(const Vec3& d, const Vec3& n) {
    return d - 2.0 * dot(d, n) * n;
}

Vec3 project_onto(const Vec3& v, const Vec3& onto) {
    if (largest_component(onto) == 0.0) {
        throw std::domain_error("project_onto: cannot project onto the zero vector");
    }
    // Through the unit vector: onto . onto would overflow for |onto| above 1e154.
    const Vec3 unit = normalize(onto);
    return dot(v, unit) * unit;
}

Vec3 perpendicular_to(const Vec3& v, const Vec3& edge) {
    return v - project_onto(v, edge);
}

Frame orthonormal_frame(const Vec3& a, const Vec3& b) {
    if (largest_component(a) == 0.0) throw std::domain_error("orthonormal_frame: a is zero");
    if (largest_component(b) == 0.0) throw std::domain_error("orthonormal_frame: b is zero");
    const Vec3 w = normalize(a);
    const Vec3 b_cross_w = cross(b, w);
    // Not "== 0": w is rounded, so for a b parallel to a, b x w is a few ulps, not zero.
    if (length(b_cross_w) <= kParallelSine * length(b)) {
        throw std::domain_error("orthonormal_frame: b is parallel to a");
    }
    Frame frame;
    frame.w = w;
    frame.u = normalize(b_cross_w);
    frame.v = cross(frame.w, frame.u);
    return frame;
}

}  // namespace raystep
