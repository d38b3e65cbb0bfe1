// Stage 4 reference solution: building the BVH, top down, with the binned surface area heuristic
// (Wald 2007, "On fast construction of SAH-based bounding volume hierarchies") or at the median.
// The binary tree is then collapsed to eight children per node (bvh_collapse.cpp).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "solutions/4_accel/bvh_binary_tree.h"

namespace raystep {

namespace {

// The SAH's cost model: visiting a binary node costs 1, testing a triangle kTriangleTestCost, a
// sphere kSphereTestCost. Measured, not guessed: the walk waits on memory and branches more than
// on arithmetic, so a triangle test priced as one node (not the textbook's two) gives leaves of a
// few triangles that save levels of nodes, and ran the bunny faster; intersect_sphere's square
// root and division make a sphere worth two. `raystep-reference bench --workload bunny --workload
// spheres --threads 1`, in builds with each price, re-measures it
// (docs/measurements/stage4-bench.md has the runs).
constexpr double kTriangleTestCost = 1.0;
constexpr double kSphereTestCost = 2.0;
// Wald 2007's bin count: a tree nearly as good as pricing every position, in O(N) per node.
constexpr int kBins = 16;
// The SAH may keep up to kMaxLeafSize (bvh_binary_tree.h) primitives in a leaf when splitting
// costs more; the median split stops at kMedianLeafSize, having no cost to weigh.
constexpr std::size_t kMedianLeafSize = 4;

struct BuildPrimitive {
    Aabb box;
    Vec3 centroid;
    std::uint32_t id;
    double test_cost;  ///< kSphereTestCost or kTriangleTestCost
};

struct Split {
    int axis = -1;
    double position = 0.0;
    double cost = std::numeric_limits<double>::infinity();
};

// The best binned SAH split of primitives [begin, end): the centroids' box cut into kBins slabs
// per axis, and every boundary between slabs priced by the areas and counts on either side.
Split best_sah_split(const std::vector<BuildPrimitive>& primitives, std::size_t begin,
                     std::size_t end, const Aabb& centroids, double parent_area) {
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
        const double low = centroids.min[axis];
        const double width = centroids.max[axis] - low;
        if (!(width > 0.0)) continue;
        std::array<Aabb, kBins> bins;
        std::array<std::size_t, kBins> counts{};
        std::array<double, kBins> test_costs{};
        const double scale = kBins / width;
        const auto bin_of = [&](double c) {
            return std::min(kBins - 1, static_cast<int>((c - low) * scale));
        };
        for (std::size_t k = begin; k < end; ++k) {
            const int b = bin_of(primitives[k].centroid[axis]);
            bins[b].add(primitives[k].box);
            ++counts[b];
            test_costs[b] += primitives[k].test_cost;
        }
        // Sweep from the right, then from the left, pricing each boundary.
        std::array<double, kBins> right_cost{};
        Aabb right;
        double right_tests = 0.0;
        for (int b = kBins - 1; b > 0; --b) {
            right.add(bins[b]);
            right_tests += test_costs[b];
            right_cost[b] = right.surface_area() * right_tests;
        }
        Aabb left;
        std::size_t left_count = 0;
        double left_tests = 0.0;
        for (int b = 0; b < kBins - 1; ++b) {
            left.add(bins[b]);
            left_count += counts[b];
            left_tests += test_costs[b];
            if (left_count == 0 || left_count == end - begin) continue;
            const double cost =
                1.0 + (left.surface_area() * left_tests + right_cost[b + 1]) / parent_area;
            if (cost < best.cost) best = {axis, low + (b + 1) / scale, cost};
        }
    }
    return best;
}

class BvhBuilder {
  public:
    BvhBuilder(std::vector<BuildPrimitive> primitives, BvhSplit split)
        : primitives_(std::move(primitives)), split_(split) {}

    /// Builds the binary tree; node 0 is the root.
    std::vector<BinaryNode> build() {
        nodes_.clear();
        if (!primitives_.empty()) build_node(0, primitives_.size(), 0);
        return std::move(nodes_);
    }

    const std::vector<BuildPrimitive>& primitives() const { return primitives_; }

  private:
    int build_node(std::size_t begin, std::size_t end, int depth) {
        const int index = static_cast<int>(nodes_.size());
        nodes_.push_back({});
        Aabb box;
        Aabb centroids;
        double test_cost = 0.0;
        for (std::size_t k = begin; k < end; ++k) {
            box.add(primitives_[k].box);
            centroids.add(primitives_[k].centroid);
            test_cost += primitives_[k].test_cost;
        }
        nodes_[index].box = box;
        nodes_[index].begin = begin;
        nodes_[index].end = end;
        nodes_[index].test_cost = test_cost;

        const std::size_t middle = split_at(begin, end, box, centroids, test_cost, depth);
        if (middle == begin) return index;  // a leaf
        const int left = build_node(begin, middle, depth + 1);
        const int right = build_node(middle, end, depth + 1);
        nodes_[index].children[0] = left;
        nodes_[index].children[1] = right;
        return index;
    }

    // Where to divide [begin, end), after reordering it; `begin` to make a leaf, which costs
    // `leaf_cost`.
    std::size_t split_at(std::size_t begin, std::size_t end, const Aabb& box, const Aabb& centroids,
                         double leaf_cost, int depth) {
        const std::size_t count = end - begin;
        const Vec3 extent = centroids.extent();
        const int axis =
            extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);

        // All centroids at one point: no plane separates them, so split by order, and only when
        // the leaf would be too big.
        if (!(extent[axis] > 0.0)) return count > kMaxLeafSize ? median(begin, end, axis) : begin;
        if (split_ == BvhSplit::median || depth >= kBvhSahDepth) {
            return count > kMedianLeafSize ? median(begin, end, axis) : begin;
        }

        const Split split = best_sah_split(primitives_, begin, end, centroids, box.surface_area());
        if (split.axis < 0) return begin;
        if (count <= kMaxLeafSize && split.cost >= leaf_cost) return begin;
        const auto middle = std::partition(
            primitives_.begin() + static_cast<long>(begin),
            primitives_.begin() + static_cast<long>(end),
            [&split](const BuildPrimitive& p) { return p.centroid[split.axis] < split.position; });
        const auto at = static_cast<std::size_t>(middle - primitives_.begin());
        // Rounding can put a centroid on the other side of the plane than its bin: never leave a
        // side empty (an empty side would repeat this node forever).
        if (at == begin || at == end) return median(begin, end, split.axis);
        return at;
    }

    // Halves [begin, end) at the median centroid along the axis.
    std::size_t median(std::size_t begin, std::size_t end, int axis) {
        const std::size_t middle = begin + (end - begin) / 2;
        std::nth_element(primitives_.begin() + static_cast<long>(begin),
                         primitives_.begin() + static_cast<long>(middle),
                         primitives_.begin() + static_cast<long>(end),
                         [axis](const BuildPrimitive& a, const BuildPrimitive& b) {
                             return a.centroid[axis] < b.centroid[axis];
                         });
        return middle;
    }

    std::vector<BuildPrimitive> primitives_;
    BvhSplit split_;
    std::vector<BinaryNode> nodes_;
};

}  // namespace

void build_bvh(Bvh::Impl& bvh, const PrimitiveList& primitives, BvhSplit split) {
    bvh.spheres = primitives.spheres;
    bvh.sphere_count = static_cast<std::uint32_t>(primitives.spheres.size());

    std::vector<BuildPrimitive> items;
    items.reserve(primitives.spheres.size() + primitives.triangles.size());
    for (std::size_t k = 0; k < primitives.spheres.size(); ++k) {
        const Aabb box = bounds_of(primitives.spheres[k]);
        items.push_back({box, box.center(), static_cast<std::uint32_t>(k), kSphereTestCost});
    }
    for (std::size_t k = 0; k < primitives.triangles.size(); ++k) {
        const Aabb box = bounds_of(primitives.triangles[k]);
        items.push_back({box, box.center(), bvh.sphere_count + static_cast<std::uint32_t>(k),
                         kTriangleTestCost});
    }

    BvhBuilder builder(std::move(items), split);
    const std::vector<BinaryNode> tree = builder.build();
    const std::vector<BuildPrimitive>& ordered = builder.primitives();

    bvh.slots.resize(ordered.size());
    bvh.slot_triangles.resize(ordered.size());
    for (std::size_t slot = 0; slot < ordered.size(); ++slot) {
        const std::uint32_t id = ordered[slot].id;
        bvh.slots[slot] = id;
        if (id >= bvh.sphere_count)
            bvh.slot_triangles[slot] = primitives.triangles[id - bvh.sphere_count];
    }
    if (!tree.empty()) {
        bvh.root_box = tree[0].box;
        // The node planes are the boxes' bounds rounded outward to float, by at most 2^-23 of
        // themselves.
        for (int axis = 0; axis < 3; ++axis) {
            bvh.plane_magnitude = std::max({bvh.plane_magnitude, std::abs(bvh.root_box.min[axis]),
                                            std::abs(bvh.root_box.max[axis])});
        }
        bvh.plane_magnitude *= 1.0 + 0x1p-22;
    }
    bvh.root = collapse_to_wide(tree, bvh);
}

}  // namespace raystep
