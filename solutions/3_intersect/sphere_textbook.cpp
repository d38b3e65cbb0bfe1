// The ray-sphere quadratic exactly as first derived, kept to measure what the stable forms fix.

#include <cmath>

#include "solutions/3_intersect/intersect_methods.h"
#include "solutions/3_intersect/hit_building.h"

namespace raystep {

std::optional<Hit> intersect_sphere_textbook(const Ray& ray, const Sphere& sphere) {
    if (!(sphere.radius > 0.0)) return std::nullopt;
    const Vec3 f = ray.origin - sphere.center;
    const double a = glm::dot(ray.direction, ray.direction);
    if (a == 0.0) return std::nullopt;
    const double b = 2.0 * glm::dot(ray.direction, f);
    const double c = glm::dot(f, f) - sphere.radius * sphere.radius;
    const double discriminant = b * b - 4.0 * a * c;
    if (!(discriminant >= 0.0)) return std::nullopt;
    const double root = std::sqrt(discriminant);
    const double t0 = (-b - root) / (2.0 * a);
    const double t1 = (-b + root) / (2.0 * a);
    return nearer_root_hit(ray, sphere, t0, t1);
}

}  // namespace raystep
