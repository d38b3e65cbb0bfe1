#pragma once

// Pieces every reference intersection test shares. The tests use GLM's inline dot and cross
// rather than stage 1's functions: they run in the innermost loop, where a call per product
// would cost more than the arithmetic.

#include <optional>

#include <glm/geometric.hpp>

#include "stages/3_intersect/intersect.h"

namespace raystep {

/// t lies in [t_min, t_max]. Written so that a NaN t is rejected.
inline bool in_ray_range(const Ray& ray, double t) {
    return t >= ray.t_min && t <= ray.t_max;
}

/// The hit at t on a triangle with barycentrics (beta, gamma); the normal is the triangle's
/// geometric normal, (p1 - p0) x (p2 - p0) normalized.
inline Hit triangle_hit(const Triangle& tri, double t, double beta, double gamma) {
    const Vec3 n = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    return {t, n / glm::length(n), beta, gamma};
}

}  // namespace raystep
