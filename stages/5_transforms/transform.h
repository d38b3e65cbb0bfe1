#pragma once

#include <optional>
#include <vector>

#include "base/scene/scene.h"
#include "base/scene/shapes.h"
#include "stages/2_rays/ray.h"
#include "stages/3_intersect/hit.h"

namespace raystep {

// Stage 5: transforms and normals. Handout: docs/stage5.md.
//
// Matrices act on column vectors, p' = M p, in homogeneous coordinates: a point has w = 1 and
// moves with the translation, a direction has w = 0 and does not.

/// `translate x y z`: p' = p + offset.
Mat4 translation(const Vec3& offset);

/// `rotate x y z degrees`: by `degrees` about the axis (x, y, z) through the origin,
/// counterclockwise when the axis points at the viewer (the right-hand rule). The axis need not
/// be unit length; a zero axis throws std::invalid_argument.
Mat4 rotation(const Vec3& axis, double degrees);

/// `scale x y z`: p' = (x p.x, y p.y, z p.z).
Mat4 scaling(const Vec3& factors);

/// A transform and its inverse, kept together: intersecting needs M^-1, shading needs M and
/// M^-T.
struct Transform {
    Mat4 matrix;   ///< M: object to world
    Mat4 inverse;  ///< M^-1: world to object
};

/// The transform of a chain of scene ops in file order, right-multiplied as OpenGL does:
/// M = M1 M2 ... Mn, so the last op written is the first applied to the object. The inverse is
/// built from the ops' own inverses, M^-1 = Mn^-1 ... M1^-1, each exact in form (negated
/// offset, opposite angle, reciprocal factors), never by inverting the product. A zero factor's
/// 1 / 0 is infinite, and M^-1 carries that infinity (NaN where a product meets it), never a
/// finite number that passes for the inverse of a transform that has none. (Scene files cannot
/// say `scale` with a zero factor: the loader rejects it.) No ops: the identity.
Transform compose(const std::vector<TransformOp>& ops);

/// The world ray in the object's frame: its origin by M^-1 as a point, its direction by M^-1 as
/// a direction, NOT renormalized, t_min and t_max unchanged. Then object-frame t equals
/// world-frame t: M (A' + t D') = A + t D for every t, so a hit found in the object frame is at
/// the same t in the world and hits of different objects compare by t directly.
Ray ray_to_object(const Transform& transform, const Ray& world_ray);

/// An object-frame point in the world: M p.
Vec3 point_to_world(const Transform& transform, const Vec3& object_point);

/// An object-frame normal in the world, unit length: M^-T n, normalized. Not M n: under a
/// non-uniform scale M n leans away from the surface, while M^-T n stays perpendicular to it.
Vec3 normal_to_world(const Transform& transform, const Vec3& object_normal);

/// The lecture's recipe for a transformed sphere (an ellipsoid): intersect the object-frame
/// sphere with ray_to_object, keep t, and take the normal to the world with normal_to_world.
std::optional<Hit> intersect_transformed_sphere(const Ray& world_ray, const Sphere& sphere,
                                                const Transform& transform);

}  // namespace raystep
