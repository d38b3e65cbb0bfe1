// The ray-sphere test the lecture asks for: the stable roots q / a and c / q, but the
// discriminant b^2 - a c as written. Kept to measure what the rewrite of the discriminant in
// intersect_sphere adds.

#include <cmath>
#include <utility>

#include "solutions/3_intersect/hit_building.h"
#include "solutions/3_intersect/intersect_methods.h"
#include "solutions/3_intersect/single_precision.h"

namespace raystep {

namespace {

// Written once for double and float (hit_building.h).
template <class RayType, class SphereType, class Real = decltype(RayType::t_min)>
std::optional<Hit> stable_roots_sphere(const RayType& ray, const SphereType& sphere) {
    if (!(sphere.radius > 0)) return std::nullopt;
    const Real a = glm::dot(ray.direction, ray.direction);
    if (a == 0) return std::nullopt;
    const auto f = ray.origin - sphere.center;
    const Real b = glm::dot(ray.direction, f);
    const Real c = glm::dot(f, f) - sphere.radius * sphere.radius;
    const Real discriminant = b * b - a * c;
    if (!(discriminant >= 0)) return std::nullopt;
    const Real q = -(b + std::copysign(std::sqrt(discriminant), b));
    Real t0 = q / a;
    Real t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    return nearer_root_hit(ray, sphere, t0, t1);
}

}  // namespace

std::optional<Hit> intersect_sphere_stable_roots(const Ray& ray, const Sphere& sphere) {
    return stable_roots_sphere(ray, sphere);
}

std::optional<Hit> intersect_sphere_stable_roots_float(const Ray& ray, const Sphere& sphere) {
    return stable_roots_sphere(FloatRay(ray), FloatSphere(sphere));
}

}  // namespace raystep
