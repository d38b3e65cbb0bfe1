#pragma once

#include <algorithm>
#include <limits>
#include <optional>

#include <glm/common.hpp>

#include "base/scene/shapes.h"
#include "stages/2_rays/ray.h"

namespace raystep {

// Stage 4: acceleration. Handout: docs/stage4.md.

/// An axis-aligned box, empty (min > max) until something is added to it.
struct Aabb {
    Vec3 min{std::numeric_limits<double>::infinity()};
    Vec3 max{-std::numeric_limits<double>::infinity()};

    void add(const Vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void add(const Aabb& box) {
        min = glm::min(min, box.min);
        max = glm::max(max, box.max);
    }
    bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
    Vec3 extent() const { return max - min; }
    Vec3 center() const { return 0.5 * (min + max); }
    /// 0 for an empty box.
    double surface_area() const {
        if (empty()) return 0.0;
        const Vec3 e = extent();
        return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
};

/// The box of the triangle's three vertices.
inline Aabb bounds_of(const Triangle& triangle) {
    Aabb box;
    box.add(triangle.p0);
    box.add(triangle.p1);
    box.add(triangle.p2);
    return box;
}

/// The box of the sphere, centre -+ radius, padded by 8 units of rounding (2^-53) of its largest
/// coordinate: c + r is rounded, and a box that is an ulp too small could lose a hit that
/// intersect_sphere reports on its very edge.
inline Aabb bounds_of(const Sphere& sphere) {
    const Vec3 c = sphere.center;
    const double magnitude =
        std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z)}) + sphere.radius;
    const double pad = 8.0 * 0x1p-53 * magnitude;
    return {c - Vec3(sphere.radius + pad), c + Vec3(sphere.radius + pad)};
}

/// Where a ray is inside a box: t from `enter` to `exit`.
struct Interval {
    double enter;
    double exit;
};

/// The part of [ray.t_min, ray.t_max] in which the ray is inside the closed box, or nullopt when
/// there is none (an empty box, a miss). `inverse_direction` is 1 / ray.direction componentwise,
/// infinite where a component is 0. Right in the cases the slab formula gets wrong: a direction
/// component of 0 with the origin exactly on that slab's plane (0 * inf is NaN), and rounding,
/// which must never make a ray miss a box it touches (docs/stage4.md, "The slab test").
std::optional<Interval> intersect_aabb(const Ray& ray, const Vec3& inverse_direction,
                                       const Aabb& box);

}  // namespace raystep
