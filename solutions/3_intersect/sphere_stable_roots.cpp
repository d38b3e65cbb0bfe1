// The ray-sphere test the lecture asks for: the stable roots q / a and c / q, but the
// discriminant b^2 - a c as written. Kept to measure what the rewrite of the discriminant in
// intersect_sphere adds.

#include <cmath>
#include <utility>

#include "solutions/3_intersect/intersect_methods.h"
#include "solutions/3_intersect/hit_building.h"

namespace raystep {

std::optional<Hit> intersect_sphere_stable_roots(const Ray& ray, const Sphere& sphere) {
    if (!(sphere.radius > 0.0)) return std::nullopt;
    const double a = glm::dot(ray.direction, ray.direction);
    if (a == 0.0) return std::nullopt;
    const Vec3 f = ray.origin - sphere.center;
    const double b = glm::dot(ray.direction, f);
    const double c = glm::dot(f, f) - sphere.radius * sphere.radius;
    const double discriminant = b * b - a * c;
    if (!(discriminant >= 0.0)) return std::nullopt;
    const double q = -(b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a;
    double t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    return nearer_root_hit(ray, sphere, t0, t1);
}

}  // namespace raystep
