#pragma once

// The steps the reference intersection tests share: the range check, normalizing, building a
// hit. The tests use GLM's inline dot and cross rather than stage 1's functions: they run in the
// innermost loop, where a call per product would cost more than the arithmetic.

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

/// Where the ray crosses the triangle's supporting plane: step 1 of the lecture's methods 1 and 2.
struct PlaneCrossing {
    double t;
    Vec3 point;   ///< ray.origin + t ray.direction
    Vec3 normal;  ///< (p1 - p0) x (p2 - p0), not normalized
};

/// nullopt when the ray is parallel to the plane, the direction is zero, the triangle has no
/// area, or the crossing is outside [t_min, t_max].
inline std::optional<PlaneCrossing> cross_supporting_plane(const Ray& ray, const Triangle& tri) {
    const Vec3 n = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    const double denominator = glm::dot(ray.direction, n);
    if (denominator == 0.0) return std::nullopt;
    const double t = glm::dot(tri.p0 - ray.origin, n) / denominator;
    if (!in_ray_range(ray, t)) return std::nullopt;
    return PlaneCrossing{t, ray.origin + t * ray.direction, n};
}

/// The hit at the nearer root t0 <= t1 of a ray-sphere quadratic in range, else at the farther;
/// nullopt when neither is in range, or when the hit point is the centre itself (a sphere too
/// small to resolve: no normal). The normal is outward, from f + t D with f = A - C.
inline std::optional<Hit> nearer_root_hit(const Ray& ray, const Sphere& sphere, double t0,
                                          double t1) {
    const double t = in_ray_range(ray, t0) ? t0 : t1;
    if (!in_ray_range(ray, t)) return std::nullopt;
    const Vec3 outward = (ray.origin - sphere.center) + t * ray.direction;
    if (outward == Vec3(0.0)) return std::nullopt;
    return Hit{t, unit_vector(outward)};
}

}  // namespace raystep
