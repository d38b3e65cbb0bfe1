// The reference BVH's collapse of its binary tree to eight children per node
// (solutions/4_accel/bvh_collapse.cpp), on binary trees made by hand: which nodes it keeps, which
// leaves it merges, and that the wide tree still holds every primitive once.

#include <vector>

#include "base/testing/catch.h"
#include "solutions/4_accel/bvh_binary_tree.h"

using namespace raystep;

namespace {

// Primitive k's box: a unit cube at 10 k along x, or, when `shared`, the one cube at the origin.
Aabb box_of(std::size_t k, bool shared) {
    const Vec3 low = shared ? Vec3(0.0) : Vec3(10.0 * static_cast<double>(k), 0.0, 0.0);
    return {low, low + Vec3(1.0)};
}

// Appends the subtree of primitives [begin, end), one triangle per binary leaf, divided at
// middle(begin, end); returns its index. The root comes first, as the builder writes it.
template <class Middle>
int add_subtree(std::vector<BinaryNode>& tree, std::size_t begin, std::size_t end, bool shared,
                Middle middle) {
    const int index = static_cast<int>(tree.size());
    tree.emplace_back();
    BinaryNode node;
    node.begin = begin;
    node.end = end;
    node.test_cost = static_cast<double>(end - begin);
    for (std::size_t k = begin; k < end; ++k)
        node.box.add(box_of(k, shared));
    if (end - begin > 1) {
        const std::size_t split = middle(begin, end);
        node.children[0] = add_subtree(tree, begin, split, shared, middle);
        node.children[1] = add_subtree(tree, split, end, shared, middle);
    }
    tree[static_cast<std::size_t>(index)] = node;
    return index;
}

std::vector<BinaryNode> balanced_tree(std::size_t primitives, bool shared) {
    std::vector<BinaryNode> tree;
    add_subtree(tree, 0, primitives, shared,
                [](std::size_t begin, std::size_t end) { return begin + (end - begin) / 2; });
    return tree;
}

// A leaf, then the rest: as deep as a binary tree over n primitives can be.
std::vector<BinaryNode> chain_tree(std::size_t primitives) {
    std::vector<BinaryNode> tree;
    add_subtree(tree, 0, primitives, false,
                [](std::size_t begin, std::size_t) { return begin + 1; });
    return tree;
}

bool is_used(const BvhNode& node, int c) {
    return node.planes[0][c] <= node.planes[1][c];
}

// How many leaves of the wide tree under `child` hold each slot; checks every node on the way
// has two children at least and every leaf at most kMaxLeafSize primitives.
void count_slots(const Bvh::Impl& bvh, BvhChild child, std::vector<int>& holders) {
    if (child.count > 0) {
        CHECK(child.count <= kMaxLeafSize);
        for (std::uint32_t slot = child.index; slot < child.index + child.count; ++slot)
            ++holders.at(slot);
        return;
    }
    const BvhNode& node = bvh.nodes.at(child.index);
    int used = 0;
    for (int c = 0; c < BvhNode::kWidth; ++c) {
        if (!is_used(node, c)) continue;
        ++used;
        count_slots(bvh, {node.child[c], node.count[c]}, holders);
    }
    CHECK(used >= 2);
}

}  // namespace

TEST_CASE("BVH collapse: a binary tree of eight far-apart leaves becomes one node of eight leaves",
          "[accel]") {
    Bvh::Impl bvh;
    const BvhChild root = collapse_to_wide(balanced_tree(8, false), bvh);
    REQUIRE(root.count == 0);
    REQUIRE(bvh.nodes.size() == 1);
    for (int c = 0; c < BvhNode::kWidth; ++c) {
        CAPTURE(c);
        CHECK(is_used(bvh.nodes[0], c));
        CHECK(bvh.nodes[0].count[c] == 1);
    }
}

TEST_CASE("BVH collapse: primitives that share one box become one leaf, not a node", "[accel]") {
    // Entering either child means entering both: a node would only add a visit.
    Bvh::Impl bvh;
    const BvhChild root = collapse_to_wide(balanced_tree(2, true), bvh);
    CHECK(bvh.nodes.empty());
    CHECK(root.index == 0);
    CHECK(root.count == 2);
}

TEST_CASE("BVH collapse: more primitives in one box than a leaf holds still get a node",
          "[accel]") {
    Bvh::Impl bvh;
    const BvhChild root = collapse_to_wide(balanced_tree(kMaxLeafSize + 1, true), bvh);
    CHECK(root.count == 0);
    std::vector<int> holders(kMaxLeafSize + 1, 0);
    count_slots(bvh, root, holders);
    CHECK(holders == std::vector<int>(kMaxLeafSize + 1, 1));
}

TEST_CASE("BVH collapse: a deep chain fills its nodes and keeps every primitive once", "[accel]") {
    // Fifteen far-apart leaves in a chain 15 deep: eight slots per node cover them with two nodes
    // (or one, where two neighbours share a leaf), never with a node per binary level.
    Bvh::Impl bvh;
    const BvhChild root = collapse_to_wide(chain_tree(15), bvh);
    CHECK(bvh.nodes.size() <= 2);
    std::vector<int> holders(15, 0);
    count_slots(bvh, root, holders);
    CHECK(holders == std::vector<int>(15, 1));
}
