// Stage 5 reference solution: rays into an object's frame, points and normals back out.

#include <glm/matrix.hpp>

#include "stages/1_vectors/vectors.h"
#include "stages/3_intersect/intersect.h"
#include "stages/5_transforms/transform.h"

namespace raystep {

Ray ray_to_object(const Transform& transform, const Ray& world_ray) {
    Ray ray = world_ray;
    ray.origin = Vec3(transform.inverse * Vec4(world_ray.origin, 1.0));
    ray.direction = Vec3(transform.inverse * Vec4(world_ray.direction, 0.0));
    return ray;
}

Vec3 point_to_world(const Transform& transform, const Vec3& object_point) {
    return Vec3(transform.matrix * Vec4(object_point, 1.0));
}

Vec3 normal_to_world(const Transform& transform, const Vec3& object_normal) {
    return normalize(Vec3(glm::transpose(transform.inverse) * Vec4(object_normal, 0.0)));
}

std::optional<Hit> intersect_transformed_sphere(const Ray& world_ray, const Sphere& sphere,
                                                const Transform& transform) {
    std::optional<Hit> hit = intersect_sphere(ray_to_object(transform, world_ray), sphere);
    if (hit) hit->normal = normal_to_world(transform, hit->normal);
    return hit;
}

}  // namespace raystep
