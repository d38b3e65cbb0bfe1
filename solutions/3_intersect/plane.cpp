// Stage 3 reference solution: ray-plane.

#include "solutions/3_intersect/triangle_hit.h"

namespace raystep {

std::optional<Hit> intersect_plane(const Ray& ray, const Plane& plane) {
    // A zero normal has no plane; D . N = 0 is a ray parallel to the plane (or a zero D).
    const double denominator = glm::dot(ray.direction, plane.normal);
    if (denominator == 0.0) return std::nullopt;
    const double t = glm::dot(plane.point - ray.origin, plane.normal) / denominator;
    if (!in_ray_range(ray, t)) return std::nullopt;
    return Hit{t, plane.normal / glm::length(plane.normal)};
}

}  // namespace raystep
