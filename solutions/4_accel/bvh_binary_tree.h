#pragma once

// The binary tree the BVH builder makes (bvh_build.cpp), before it is collapsed to wide nodes
// (bvh_collapse.cpp): the tree the lecture draws.

#include <cstddef>
#include <vector>

#include "solutions/4_accel/bvh_layout.h"

namespace raystep {

/// A leaf holds at most this many primitives, in the binary tree and in the wide one.
inline constexpr std::size_t kMaxLeafSize = 8;

/// A node: a leaf, or two children. Either way it covers the primitives [begin, end) of the
/// build order, since the builder splits a range into two neighbouring ranges.
struct BinaryNode {
    Aabb box;
    std::size_t begin = 0;
    std::size_t end = 0;
    double test_cost = 0.0;  ///< of every primitive in [begin, end), in the SAH's units
    int children[2] = {-1, -1};

    bool is_leaf() const { return children[0] < 0; }
};

/// Writes the binary tree (node 0 its root) into `bvh.nodes` as wide nodes; returns the root.
/// Slot k of the wide tree's leaves is primitive k of the build order.
BvhChild collapse_to_wide(const std::vector<BinaryNode>& tree, Bvh::Impl& bvh);

}  // namespace raystep
