// Stage 3 reference solution: ray-plane.

#include "solutions/3_intersect/hit_building.h"
#include "solutions/3_intersect/single_precision.h"

namespace raystep {

namespace {

// Written once for double and float (hit_building.h).
template <class RayType, class PlaneType, class Real = decltype(RayType::t_min)>
std::optional<Hit> ray_plane(const RayType& ray, const PlaneType& plane) {
    // D . N = 0 is a ray parallel to the plane, a zero D or a zero N: a miss.
    const Real denominator = glm::dot(ray.direction, plane.normal);
    if (denominator == 0) return std::nullopt;
    const Real t = glm::dot(plane.point - ray.origin, plane.normal) / denominator;
    if (!in_ray_range(ray, t)) return std::nullopt;
    return Hit{t, Vec3(unit_vector(plane.normal))};
}

}  // namespace

std::optional<Hit> intersect_plane(const Ray& ray, const Plane& plane) {
    return ray_plane(ray, plane);
}

std::optional<Hit> intersect_plane_float(const Ray& ray, const Plane& plane) {
    return ray_plane(FloatRay(ray), FloatPlane(plane));
}

}  // namespace raystep
