#pragma once

// The reference BVH's memory layout. The tree is built binary, as the lecture builds it, then
// collapsed to eight children per node: a full tree then has a third as many levels, and every
// level is a dependent memory read and a branch the processor cannot predict, which is what
// single-ray traversal waits on. Eight children rather than four visit fewer nodes per ray and ran
// faster on the bunny; `raystep-reference bench --workload bunny --threads 1`, in builds with each
// width, re-measures it (docs/measurements/stage4-bench.md has the runs).

#include <cstdint>
#include <limits>
#include <vector>

#include "stages/4_accel/bvh.h"

namespace raystep {

/// An inner node: the boxes of its eight children, in float rounded outward (a box may grow by
/// an ulp, never shrink, so no hit is lost), and where each child is. planes[2 axis + side][c]
/// is child c's minimum (side 0) or maximum (side 1) along the axis: a ray picks its near plane
/// on each axis by the sign of its direction, without comparing, and reads the children's side
/// by side, to test four together. An unused child has the empty box (min +inf, max -inf),
/// which no ray enters.
struct alignas(64) BvhNode {
    static constexpr int kWidth = 8;
    float planes[6][kWidth];
    std::uint32_t child[kWidth];  ///< an inner child's node index, or a leaf's first slot
    std::uint32_t count[kWidth];  ///< 0 for an inner child; a leaf's number of primitives
};
static_assert(sizeof(BvhNode) == 256, "one node, four cache lines");

/// A child of a node, or the root: an inner node or a range of leaf slots.
struct BvhChild {
    std::uint32_t index = 0;
    std::uint32_t count = 0;  ///< 0: an inner node
};

struct Bvh::Impl {
    std::vector<BvhNode> nodes;
    BvhChild root;
    Aabb root_box;                 ///< in double: the whole scene, tested once per ray
    double plane_magnitude = 0.0;  ///< no node's plane is larger in magnitude (node_test.h)

    /// Primitive ids in leaf order: 0 to S - 1 are the spheres, S onwards the triangles.
    std::vector<std::uint32_t> slots;
    /// The triangle in each triangle slot, copied in leaf order so a leaf's tests read memory in
    /// sequence (sphere slots hold an unused triangle).
    std::vector<Triangle> slot_triangles;
    std::vector<Sphere> spheres;
    std::uint32_t sphere_count = 0;
};

/// Below this depth the builder splits by the SAH, from it on at the median (bvh_build.cpp), so
/// that no input can make the tree deeper than kBvhMaxDepth.
inline constexpr int kBvhSahDepth = 64;

/// The deepest binary tree build_bvh makes: a median split halves its primitives, and primitive
/// ids are 32 bits, so at most that many median levels follow the SAH's. Collapsing to wide nodes
/// makes no tree deeper.
inline constexpr int kBvhMaxDepth =
    kBvhSahDepth + std::numeric_limits<decltype(BvhChild::index)>::digits;

/// The traversal's fixed stack: at most seven pending nodes per level of the tree (the nearest
/// of eight children is visited at once, never pushed), over the kBvhMaxDepth + 1 levels.
inline constexpr int kBvhStackSize = (BvhNode::kWidth - 1) * (kBvhMaxDepth + 1);

/// Builds the tree over the primitives with the given split rule.
void build_bvh(Bvh::Impl& bvh, const PrimitiveList& primitives, BvhSplit split);

}  // namespace raystep
