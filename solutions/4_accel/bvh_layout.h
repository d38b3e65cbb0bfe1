#pragma once

// The reference BVH's memory layout: a binary tree stored depth-first, each node holding its two
// children's boxes so that one 64-byte cache line decides which children a ray enters.

#include <cstdint>
#include <vector>

#include "stages/4_accel/bvh.h"

namespace raystep {

/// One inner node: the boxes of its two children, in float rounded outward (a box may grow by an
/// ulp, never shrink, so no hit is lost), and where each child is. planes[2 axis + side][c] is
/// child c's minimum (side 0) or maximum (side 1) along the axis: a ray picks its near plane on
/// each axis by the sign of its direction, without comparing, and finds both children's side by
/// side, to test them together.
struct alignas(64) BvhNode {
    float planes[6][2];
    std::uint32_t child[2];  ///< an inner child's node index, or a leaf's first primitive slot
    std::uint32_t count[2];  ///< 0 for an inner child; a leaf's number of primitives
};
static_assert(sizeof(BvhNode) == 64, "one node, one cache line");

/// A child of a node, or the root: an inner node or a range of leaf slots.
struct BvhChild {
    std::uint32_t index = 0;
    std::uint32_t count = 0;  ///< 0: an inner node
};

struct Bvh::Impl {
    std::vector<BvhNode> nodes;
    BvhChild root;
    Aabb root_box;  ///< in double: the whole scene, tested once per ray

    /// Primitive ids in leaf order: 0 to S - 1 are the spheres, S onwards the triangles.
    std::vector<std::uint32_t> slots;
    /// The triangle in each triangle slot, copied in leaf order so a leaf's tests read memory in
    /// sequence (sphere slots hold an unused triangle).
    std::vector<Triangle> slot_triangles;
    std::vector<Sphere> spheres;
    std::uint32_t sphere_count = 0;
};

/// The deepest tree build_bvh makes is 97 levels (bvh_build.cpp, kSahDepth): a traversal keeps
/// at most one pending node per level.
inline constexpr int kBvhStackSize = 128;

/// Builds the tree over the primitives with the given split rule.
void build_bvh(Bvh::Impl& bvh, const PrimitiveList& primitives, BvhSplit split);

}  // namespace raystep
