#pragma once

// The steps the reference intersection tests share: the range check, normalizing, building a
// hit. The tests use GLM's inline dot and cross rather than stage 1's functions: they run in the
// innermost loop, where a call per product would cost more than the arithmetic.
//
// Each step is written for any precision: the tests run on Ray and the shapes of the scene (in
// double) as the renderer calls them, and on their single-precision copies (single_precision.h)
// for the speed-against-error study. Real is the precision of the arithmetic.

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "stages/3_intersect/intersect.h"

namespace raystep {

/// t lies in [t_min, t_max] and is finite. Written so that a NaN t is rejected; the finite test
/// rejects the t = inf that dividing by a subnormal denominator gives when t_max is infinite.
template <class RayType, class Real>
bool in_ray_range(const RayType& ray, Real t) {
    return t >= ray.t_min && t <= ray.t_max && std::isfinite(t);
}

/// v / |v|, scaled by its largest component first so that |v|^2 can neither overflow (|v| above
/// 1e154 in double, 1e19 in float) nor underflow. NaN for a zero v: callers rule that out.
template <class Vector>
Vector unit_vector(const Vector& v) {
    const Vector scaled = v / std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return scaled / glm::length(scaled);
}

/// The hit at t on a triangle with barycentrics (beta, gamma); the normal is the triangle's
/// geometric normal, (p1 - p0) x (p2 - p0) normalized. nullopt for a degenerate triangle (a zero
/// normal): a test can find a rounding-sized determinant where the exact one is zero (the
/// watertight test's sheared vertices are rounded), and the contract says such a triangle is a
/// miss, never a hit with a NaN normal.
template <class TriangleType, class Real>
std::optional<Hit> triangle_hit(const TriangleType& tri, Real t, Real beta, Real gamma) {
    const auto n = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    if (n == decltype(n)(0)) return std::nullopt;
    return Hit{t, Vec3(unit_vector(n)), beta, gamma};
}

/// Where the ray crosses the triangle's supporting plane: step 1 of the lecture's methods 1 and 2.
template <class Real>
struct PlaneCrossing {
    Real t;
    glm::vec<3, Real> point;   ///< ray.origin + t ray.direction
    glm::vec<3, Real> normal;  ///< (p1 - p0) x (p2 - p0), not normalized
};

/// nullopt when the ray is parallel to the plane, the direction is zero, the triangle has no
/// area, or the crossing is outside [t_min, t_max].
template <class RayType, class TriangleType, class Real = decltype(RayType::t_min)>
std::optional<PlaneCrossing<Real>> cross_supporting_plane(const RayType& ray,
                                                          const TriangleType& tri) {
    const auto n = glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    const Real denominator = glm::dot(ray.direction, n);
    if (denominator == 0) return std::nullopt;
    const Real t = glm::dot(tri.p0 - ray.origin, n) / denominator;
    if (!in_ray_range(ray, t)) return std::nullopt;
    return PlaneCrossing<Real>{t, ray.origin + t * ray.direction, n};
}

/// The hit at the nearer root t0 <= t1 of a ray-sphere quadratic in range, else at the farther;
/// nullopt when neither is in range, or when the hit point is the centre itself (a sphere too
/// small to resolve: no normal). The normal is outward, from f + t D with f = A - C.
template <class RayType, class SphereType, class Real>
std::optional<Hit> nearer_root_hit(const RayType& ray, const SphereType& sphere, Real t0, Real t1) {
    const Real t = in_ray_range(ray, t0) ? t0 : t1;
    if (!in_ray_range(ray, t)) return std::nullopt;
    const auto outward = (ray.origin - sphere.center) + t * ray.direction;
    if (outward == decltype(outward)(0)) return std::nullopt;
    return Hit{t, Vec3(unit_vector(outward))};
}

}  // namespace raystep
