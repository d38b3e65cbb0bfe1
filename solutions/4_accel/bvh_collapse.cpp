// Stage 4 reference solution: collapsing the binary BVH to eight children per node.
//
// Which binary nodes disappear is chosen for the least SAH cost of the wide tree, by dynamic
// programming from the leaves up (Ylitie, Karras, Laine 2017, "Efficient Incoherent Ray Traversal
// on GPUs Through Compressed Wide BVHs"). Within a wide node's eight slots a binary subtree either
// takes one slot, as a wide node of its own or as one leaf of all its primitives, or shares its
// slots between its two subtrees. The simpler greedy collapse, opening the largest child until
// there are eight, leaves many nodes with only two or three children; priced by the SAH, the
// wide tree has about half as many nodes and the walk runs faster (`raystep-reference bench
// --workload bunny --threads 1`; docs/measurements/stage4-bench.md has the runs).

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "solutions/4_accel/bvh_binary_tree.h"

namespace raystep {

namespace {

// Visiting a wide node, in the SAH's units (testing a triangle costs 1, bvh_build.cpp): the price
// at which merging a subtree into one leaf beats giving it a node. The speed is flat from 1.5 to
// 3 and lower at 1, the binary build's price, which merges no leaves; 2 lies in the middle of the
// flat range (`raystep-reference bench --workload bunny --threads 1` in a build of each).
constexpr double kWideNodeCost = 2.0;

constexpr int kWidth = BvhNode::kWidth;

// The least cost of filling at most k slots of a wide node with a subtree, at [k - 1]. The cost
// of a child is its box's area times what entering it costs (the SAH), so the root's cost is
// what a ray that enters the scene is expected to cost.
using Costs = std::array<double, kWidth>;

// How a subtree fills its slots: as one child (both 0), or left_slots for its left subtree and
// right_slots for its right.
struct Choice {
    std::uint8_t left_slots = 0;
    std::uint8_t right_slots = 0;
};

// For every binary node, its cheapest way to fill one to eight slots, then the wide nodes they
// make.
class WideCollapse {
  public:
    explicit WideCollapse(const std::vector<BinaryNode>& tree)
        : tree_(tree), choices_(tree.size()), as_one_(tree.size()) {
        solve(0);
    }

    // The subtree at `index` as one child of a wide node: a leaf, or a wide node written now.
    BvhChild emit(int index, Bvh::Impl& bvh) const {
        const BinaryNode& node = tree_[static_cast<std::size_t>(index)];
        const OneChild& one = as_one_[static_cast<std::size_t>(index)];
        if (one.is_leaf) {
            return {static_cast<std::uint32_t>(node.begin),
                    static_cast<std::uint32_t>(node.end - node.begin)};
        }
        std::vector<int> children;
        gather(node.children[0], one.split.left_slots, children);
        gather(node.children[1], one.split.right_slots, children);

        const std::size_t packed = bvh.nodes.size();
        bvh.nodes.push_back({});
        for (std::size_t c = 0; c < kWidth; ++c) {
            const Aabb box =
                c < children.size() ? tree_[static_cast<std::size_t>(children[c])].box : Aabb{};
            store_box(box, bvh.nodes[packed], static_cast<int>(c));
        }
        for (std::size_t c = 0; c < children.size(); ++c) {
            const BvhChild child = emit(children[c], bvh);
            bvh.nodes[packed].child[c] = child.index;
            bvh.nodes[packed].count[c] = child.count;
        }
        return {static_cast<std::uint32_t>(packed), 0};
    }

  private:
    // A subtree as one child: a leaf of all its primitives, or a wide node whose eight slots its
    // two subtrees share.
    struct OneChild {
        bool is_leaf = true;
        Choice split;
    };

    // Fills in the choices of the subtree at `index`, children first, and returns its costs.
    Costs solve(int index) {
        const std::size_t at = static_cast<std::size_t>(index);
        const BinaryNode& node = tree_[at];
        const double area = node.box.surface_area();
        Costs costs;
        if (node.is_leaf()) {
            costs.fill(area * node.test_cost);
            return costs;
        }
        const Costs left = solve(node.children[0]);
        const Costs right = solve(node.children[1]);
        // The cheapest way for the two subtrees to share k slots, for k = 2 to 8.
        Costs shared;
        std::array<Choice, kWidth> shares;
        for (int slots = 2; slots <= kWidth; ++slots) {
            shared[slots - 1] = std::numeric_limits<double>::infinity();
            for (int left_slots = 1; left_slots < slots; ++left_slots) {
                const int right_slots = slots - left_slots;
                const double cost = left[left_slots - 1] + right[right_slots - 1];
                if (cost < shared[slots - 1]) {
                    shared[slots - 1] = cost;
                    shares[slots - 1] = {static_cast<std::uint8_t>(left_slots),
                                         static_cast<std::uint8_t>(right_slots)};
                }
            }
        }

        // One slot: a wide node whose eight slots the subtrees share, or one leaf.
        OneChild& one = as_one_[at];
        one.is_leaf = false;
        one.split = shares[kWidth - 1];
        costs[0] = area * kWideNodeCost + shared[kWidth - 1];
        if (node.end - node.begin <= kMaxLeafSize && area * node.test_cost <= costs[0]) {
            one.is_leaf = true;
            costs[0] = area * node.test_cost;
        }
        // k slots: shared between the subtrees, or fewer when sharing costs no less.
        for (int slots = 2; slots <= kWidth; ++slots) {
            if (shared[slots - 1] < costs[slots - 2]) {
                costs[slots - 1] = shared[slots - 1];
                choices_[at][slots - 1] = shares[slots - 1];
            } else {
                costs[slots - 1] = costs[slots - 2];
                choices_[at][slots - 1] = choices_[at][slots - 2];
            }
        }
        return costs;
    }

    // The subtrees that fill at most `slots` slots for the subtree at `index`, in tree order.
    void gather(int index, int slots, std::vector<int>& children) const {
        const Choice& choice = choices_[static_cast<std::size_t>(index)][slots - 1];
        if (choice.left_slots == 0) {
            children.push_back(index);
            return;
        }
        const BinaryNode& node = tree_[static_cast<std::size_t>(index)];
        gather(node.children[0], choice.left_slots, children);
        gather(node.children[1], choice.right_slots, children);
    }

    // Child c's box in the node, in float bounds that contain the double ones: rounded down for
    // minima, up for maxima.
    static void store_box(const Aabb& box, BvhNode& node, int c) {
        for (int axis = 0; axis < 3; ++axis) {
            float low = static_cast<float>(box.min[axis]);
            float high = static_cast<float>(box.max[axis]);
            if (static_cast<double>(low) > box.min[axis]) {
                low = std::nextafter(low, -std::numeric_limits<float>::infinity());
            }
            if (static_cast<double>(high) < box.max[axis]) {
                high = std::nextafter(high, std::numeric_limits<float>::infinity());
            }
            node.planes[2 * axis][c] = low;
            node.planes[2 * axis + 1][c] = high;
        }
    }

    const std::vector<BinaryNode>& tree_;
    std::vector<std::array<Choice, kWidth>> choices_;  ///< [index][k - 1]: filling at most k
    std::vector<OneChild> as_one_;
};

}  // namespace

BvhChild collapse_to_wide(const std::vector<BinaryNode>& tree, Bvh::Impl& bvh) {
    bvh.nodes.clear();
    if (tree.empty()) return {};
    return WideCollapse(tree).emit(0, bvh);
}

}  // namespace raystep
