#pragma once

// Pieces every reference intersection test shares. The tests use GLM's inline dot and cross
// rather than stage 1's functions: they run in the innermost loop, where a call per product
// would cost more than the arithmetic.

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "stages/3_intersect/intersect.h"

namespace raystep {

/// t lies in [t_min, t_max] and is finite. Written so that a NaN t is rejected; the finite test
/// rejects the t = inf that dividing by a subnormal denominator gives when t_max is infinite.
inline bool in_ray_range(const Ray& ray, double t) {
    return t >= ray.t_min && t <= ray.t_max && std::isfinite(t);
}

/// v / |v|, scaled by its largest component first so that |v|^2 can neither overflow (|v| above
/// 1e154) nor underflow (below 1e-154). NaN for a zero v: callers rule that out.
inline Vec3 unit_vector(const Vec3& v) {
    const Vec3 scaled = v / std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return scaled / glm::length(scaled);
}

/// The hit at t on a triangle with barycentrics (beta, gamma); the normal is the triangle's
/// geometric normal, (p1 - p0) x (p2 - p0) normalized. nullopt for a degenerate triangle (a zero
/// normal): a test can find a rounding-sized determinant where the exact one is zero (the
/// watertight test's sheared vertices are rounded), and the contract says such a triangle is a
/// miss, never a hit with a NaN normal.
inline std::optional<Hit> triangle_hit(const Triangle& tri, double t, double beta, double gamma) {
    const Vec3 n = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    if (n == Vec3(0.0)) return std::nullopt;
    return Hit{t, unit_vector(n), beta, gamma};
}

}  // namespace raystep
