// Stage 5: rays into an object's frame, points and normals back out. Handout: docs/stage5.md.

#include "base/errors/not_implemented.h"
#include "stages/5_transforms/transform.h"

namespace raystep {

Ray ray_to_object(const Transform& transform, const Ray& world_ray) {
    // Origin: M^-1 (A, 1). Direction: M^-1 (D, 0), and do NOT normalize it: then the object
    // ray reaches M^-1 R(t) at the same t, and t_min, t_max carry over as they are.
    RAYSTEP_TODO(5, "ray_to_object", "Intersecting a transformed object");
}

Vec3 point_to_world(const Transform& transform, const Vec3& object_point) {
    // M (p, 1), keeping x, y, z.
    RAYSTEP_TODO(5, "point_to_world", "Intersecting a transformed object");
}

Vec3 normal_to_world(const Transform& transform, const Vec3& object_normal) {
    // (M^-1)^T n, then normalize: a normal is not a direction on the surface. A tangent t
    // with n . t = 0 goes to M t, and (M^-T n) . (M t) = n . t = 0 keeps it perpendicular.
    RAYSTEP_TODO(5, "normal_to_world", "Transforming normals");
}

std::optional<Hit> intersect_transformed_sphere(const Ray& world_ray, const Sphere& sphere,
                                                const Transform& transform) {
    // Move the ray into the sphere's frame (ray_to_object), intersect there with stage 3's
    // intersect_sphere, keep t as it is and bring the normal out with normal_to_world.
    RAYSTEP_TODO(5, "intersect_transformed_sphere", "Intersecting a transformed object");
}

}  // namespace raystep
