#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "stages/3_intersect/intersect.h"
#include "stages/4_accel/aabb.h"
#include "stages/4_accel/bvh.h"
#include "stages/5_transforms/transform.h"

namespace raystep {

// Instancing, as the lecture puts it: keep one copy of an object's geometry in its own frame and
// place it in the world by a transform, intersecting the untransformed object with the
// inverse-transformed ray. A thousand bunnies are then one bunny and a thousand matrices.

/// Spheres and triangles in their own (object) frame, with a BVH from stage 4 when there are
/// enough of them to gain from one (kBvhFromPrimitives, as for the world's): built once and
/// shared by every instance that places it.
struct InstanceGeometry {
    PrimitiveList primitives;  ///< spheres and triangles only; planes stay in the world
    std::optional<Bvh> bvh;
    Aabb bounds;  ///< of every primitive, in the object frame
    /// The scene's numbers of primitives.spheres and .triangles, where the geometry gathers
    /// primitives written one by one; empty for a mesh definition, whose triangle k is its
    /// instance's first_triangle + k.
    std::vector<std::size_t> sphere_ids;
    std::vector<std::size_t> triangle_ids;
};

/// Builds the geometry's bounds and, from kBvhFromPrimitives spheres and triangles on, its BVH
/// (stage 4). The ids are left as given.
void finish_geometry(InstanceGeometry& geometry);

/// An InstanceGeometry placed in the world.
struct Instance {
    std::size_t geometry = 0;            ///< index into RenderScene::instance_geometries
    std::optional<Transform> transform;  ///< object to world; none: the geometry is in the world
    /// The largest entry of M^-1 M - I as computed: how far the frame the intersection sees
    /// (through M^-1) and the one points come back through (M) disagree, for error bounds.
    double inverse_residual = 0.0;
    /// det M < 0: M mirrors, and a triangle's normal M^-T n points against the winding of its
    /// world vertices M p, whose (p1 - p0) x (p2 - p0) the scene format calls its normal.
    bool mirrors = false;
    std::size_t first_triangle = 0;  ///< for a mesh definition: the scene's number of triangle 0
    /// The geometry's bounds carried to the world by M, widened to hold every point an object-frame
    /// test can report (instance.cpp says by how much).
    Aabb world_bounds;
};

/// Sets the instance's residual and world bounds from its transform and geometry.
void place_instance(Instance& instance, const InstanceGeometry& geometry);

/// The closest hit of the world ray on the instance, as closest_hit over its primitives in the
/// object frame finds it: the ray by ray_to_object (t is the same in both frames), the normal back
/// by normal_to_world (stage 5). `index` is the scene's number of the primitive hit. Adds the
/// geometry BVH's nodes and tests to `stats` when given.
std::optional<PrimitiveHit> instance_closest_hit(const Instance& instance,
                                                 const InstanceGeometry& geometry, const Ray& ray,
                                                 TraversalStats* stats);

/// True when the world ray meets any primitive of the instance within [t_min, t_max].
bool instance_occluded(const Instance& instance, const InstanceGeometry& geometry, const Ray& ray);

}  // namespace raystep
