// Stage 3 reference solution: ray-plane.

#include "solutions/3_intersect/hit_building.h"

namespace raystep {

std::optional<Hit> intersect_plane(const Ray& ray, const Plane& plane) {
    // D . N = 0 is a ray parallel to the plane, a zero D or a zero N: a miss.
    const double denominator = glm::dot(ray.direction, plane.normal);
    if (denominator == 0.0) return std::nullopt;
    const double t = glm::dot(plane.point - ray.origin, plane.normal) / denominator;
    if (!in_ray_range(ray, t)) return std::nullopt;
    return Hit{t, unit_vector(plane.normal)};
}

}  // namespace raystep
