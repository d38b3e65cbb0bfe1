// The ray-sphere quadratic exactly as first derived, kept to measure what the stable forms fix.

#include <cmath>

#include "solutions/3_intersect/hit_building.h"
#include "solutions/3_intersect/intersect_methods.h"
#include "solutions/3_intersect/single_precision.h"

namespace raystep {

namespace {

// Written once for double and float (hit_building.h).
template <class RayType, class SphereType, class Real = decltype(RayType::t_min)>
std::optional<Hit> textbook_sphere(const RayType& ray, const SphereType& sphere) {
    if (!(sphere.radius > 0)) return std::nullopt;
    const auto f = ray.origin - sphere.center;
    const Real a = glm::dot(ray.direction, ray.direction);
    if (a == 0) return std::nullopt;
    const Real b = 2 * glm::dot(ray.direction, f);
    const Real c = glm::dot(f, f) - sphere.radius * sphere.radius;
    const Real discriminant = b * b - 4 * a * c;
    if (!(discriminant >= 0)) return std::nullopt;
    const Real root = std::sqrt(discriminant);
    const Real t0 = (-b - root) / (2 * a);
    const Real t1 = (-b + root) / (2 * a);
    return nearer_root_hit(ray, sphere, t0, t1);
}

}  // namespace

std::optional<Hit> intersect_sphere_textbook(const Ray& ray, const Sphere& sphere) {
    return textbook_sphere(ray, sphere);
}

std::optional<Hit> intersect_sphere_textbook_float(const Ray& ray, const Sphere& sphere) {
    return textbook_sphere(FloatRay(ray), FloatSphere(sphere));
}

}  // namespace raystep
