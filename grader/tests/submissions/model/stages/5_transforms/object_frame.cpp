// Stage 5: rays into an object's frame, points and normals back out. Handout: docs/stage5.md.

#include <glm/matrix.hpp>

#include "stages/1_vectors/vectors.h"
#include "stages/3_intersect/intersect.h"
#include "stages/5_transforms/transform.h"

namespace raystep {

Ray ray_to_object(const Transform& transform, const Ray& world_ray) {
    // The origin as a point (w = 1), the direction as a direction (w = 0) and NOT normalized:
    // then t is the same in both frames, and t_min, t_max carry over.
    Ray ray = world_ray;
    ray.origin = Vec3(transform.inverse * Vec4(world_ray.origin, 1.0));
    ray.direction = Vec3(transform.inverse * Vec4(world_ray.direction, 0.0));
    return ray;
}

Vec3 point_to_world(const Transform& transform, const Vec3& object_point) {
    return Vec3(transform.matrix * Vec4(object_point, 1.0));
}

Vec3 normal_to_world(const Transform& transform, const Vec3& object_normal) {
    // M^-T n keeps the normal perpendicular to the transformed surface; M n would not.
    const Mat4 inverse_transpose = glm::transpose(transform.inverse);
    return normalize(Vec3(inverse_transpose * Vec4(object_normal, 0.0)));
}

std::optional<Hit> intersect_transformed_sphere(const Ray& world_ray, const Sphere& sphere,
                                                const Transform& transform) {
    std::optional<Hit> hit = intersect_sphere(ray_to_object(transform, world_ray), sphere);
    if (hit) hit->normal = normal_to_world(transform, hit->normal);  // t stays as it is
    return hit;
}

}  // namespace raystep
