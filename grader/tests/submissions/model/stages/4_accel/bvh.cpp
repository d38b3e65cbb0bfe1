// Stage 4: the bounding volume hierarchy. Handout: docs/stage4.md, "Building a BVH" and
// "Walking a BVH".

#include "stages/4_accel/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace raystep {

// A binary tree in a flat array: node 0 is the root; an inner node has two children, a leaf a
// range of `order`. Primitives are numbered as closest_hit numbers them: spheres 0 to S - 1,
// then triangles from S.
struct Bvh::Impl {
    struct Node {
        Aabb box;
        int left = -1;  ///< -1 for a leaf
        int right = -1;
        std::uint32_t first = 0;  ///< a leaf's primitives: order[first .. first + count)
        std::uint32_t count = 0;
    };
    std::vector<Node> nodes;
    std::vector<std::uint32_t> order;
    std::vector<Sphere> spheres;
    std::vector<Triangle> triangles;
};

namespace {

// The SAH's costs: visiting a node 1, testing a primitive 2 (a triangle test costs more than a
// box test). Leaves hold at most 8 primitives (SAH) or 4 (median).
constexpr double kNodeCost = 1.0;
constexpr double kTestCost = 2.0;
constexpr int kBins = 16;
constexpr std::size_t kMaxLeaf = 8;
constexpr std::size_t kMedianLeaf = 4;
// Below this depth every split is at the median, which halves: the tree stays shallow whatever
// the input, and the traversal's stack below (kStackSize) can hold a node per level.
constexpr int kSahDepth = 64;
constexpr int kStackSize = 128;

// A box is skipped only when it starts more than this (relative) beyond the best hit: a hit's t
// and the box's entry are rounded separately, and a hit can come out a few ulps before the box
// that holds it. 2^-40 is a thousand times those roundings.
constexpr double kPruneSlack = 0x1p-40;

double search_limit(double t) {
    return t + kPruneSlack * std::abs(t);
}

struct Item {
    Aabb box;
    Vec3 centroid;
    std::uint32_t id;
};

int longest_axis(const Vec3& extent) {
    if (extent.x >= extent.y && extent.x >= extent.z) return 0;
    return extent.y >= extent.z ? 1 : 2;
}

class Builder {
  public:
    Builder(Bvh::Impl& bvh, std::vector<Item> items, BvhSplit split)
        : bvh_(bvh), items_(std::move(items)), split_(split) {}

    void build() {
        if (items_.empty()) return;
        build_node(0, items_.size(), 0);
        for (const Item& item : items_) bvh_.order.push_back(item.id);
    }

  private:
    int build_node(std::size_t begin, std::size_t end, int depth) {
        const int index = static_cast<int>(bvh_.nodes.size());
        bvh_.nodes.push_back({});
        Aabb box;
        Aabb centroids;
        for (std::size_t k = begin; k < end; ++k) {
            box.add(items_[k].box);
            centroids.add(items_[k].centroid);
        }
        bvh_.nodes[index].box = box;

        const std::size_t middle = choose_split(begin, end, box, centroids, depth);
        if (middle == begin) {
            bvh_.nodes[index].first = static_cast<std::uint32_t>(begin);
            bvh_.nodes[index].count = static_cast<std::uint32_t>(end - begin);
            return index;
        }
        const int left = build_node(begin, middle, depth + 1);
        const int right = build_node(middle, end, depth + 1);
        bvh_.nodes[index].left = left;
        bvh_.nodes[index].right = right;
        return index;
    }

    // Where to cut [begin, end) after reordering it; `begin` makes a leaf.
    std::size_t choose_split(std::size_t begin, std::size_t end, const Aabb& box,
                             const Aabb& centroids, int depth) {
        const std::size_t count = end - begin;
        const int axis = longest_axis(centroids.extent());
        // All centroids at one point: no plane separates them; halve by order if too many
        if (!(centroids.extent()[axis] > 0.0)) return count > kMaxLeaf ? median(begin, end, axis) : begin;
        if (split_ == BvhSplit::median || depth >= kSahDepth) {
            return count > kMedianLeaf ? median(begin, end, axis) : begin;
        }
        return sah(begin, end, box, centroids);
    }

    std::size_t median(std::size_t begin, std::size_t end, int axis) {
        const std::size_t middle = begin + (end - begin) / 2;
        std::nth_element(items_.begin() + static_cast<long>(begin), items_.begin() + static_cast<long>(middle),
                         items_.begin() + static_cast<long>(end),
                         [axis](const Item& a, const Item& b) { return a.centroid[axis] < b.centroid[axis]; });
        return middle;
    }

    // Binned SAH (Wald 2007): 16 slabs of the centroids' box per axis, and each of the 15
    // boundaries priced as C = C_node + C_test (A_left N_left + A_right N_right) / A_parent.
    std::size_t sah(std::size_t begin, std::size_t end, const Aabb& box, const Aabb& centroids) {
        const std::size_t count = end - begin;
        const double parent_area = box.surface_area();
        double best_cost = std::numeric_limits<double>::infinity();
        int best_axis = -1;
        double best_position = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            const double low = centroids.min[axis];
            const double width = centroids.max[axis] - low;
            if (!(width > 0.0)) continue;
            const double scale = kBins / width;
            std::array<Aabb, kBins> bins;
            std::array<std::size_t, kBins> counts{};
            for (std::size_t k = begin; k < end; ++k) {
                const int b = std::min(kBins - 1, static_cast<int>((items_[k].centroid[axis] - low) * scale));
                bins[b].add(items_[k].box);
                ++counts[b];
            }
            // Sweep from the right to know each boundary's right side, then from the left
            std::array<double, kBins> right_cost{};
            Aabb right;
            std::size_t right_count = 0;
            for (int b = kBins - 1; b > 0; --b) {
                right.add(bins[b]);
                right_count += counts[b];
                right_cost[b] = right.surface_area() * static_cast<double>(right_count);
            }
            Aabb left;
            std::size_t left_count = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                left.add(bins[b]);
                left_count += counts[b];
                if (left_count == 0 || left_count == count) continue;
                const double cost =
                    kNodeCost + kTestCost * (left.surface_area() * static_cast<double>(left_count) + right_cost[b + 1]) /
                                    parent_area;
                if (cost < best_cost) {
                    best_cost = cost;
                    best_axis = axis;
                    best_position = low + (b + 1) / scale;
                }
            }
        }
        // A leaf when no cut beats testing every primitive, if the leaf is small enough
        const double leaf_cost = kTestCost * static_cast<double>(count);
        if (best_axis < 0 || (best_cost >= leaf_cost && count <= kMaxLeaf)) {
            return count > kMaxLeaf ? median(begin, end, longest_axis(centroids.extent())) : begin;
        }
        const auto middle = std::partition(items_.begin() + static_cast<long>(begin), items_.begin() + static_cast<long>(end),
                                           [&](const Item& item) { return item.centroid[best_axis] < best_position; });
        const auto at = static_cast<std::size_t>(middle - items_.begin());
        // Rounding can put a centroid on the other side of the plane than its bin: never leave
        // a side empty, which would repeat this node forever
        if (at == begin || at == end) return median(begin, end, best_axis);
        return at;
    }

    Bvh::Impl& bvh_;
    std::vector<Item> items_;
    BvhSplit split_;
};

// The hit of primitive `id`, numbered and reported as closest_hit does.
std::optional<PrimitiveHit> test_primitive(const Bvh::Impl& bvh, std::uint32_t id, const Ray& ray) {
    if (id < bvh.spheres.size()) {
        if (const std::optional<Hit> hit = intersect_sphere(ray, bvh.spheres[id])) {
            return PrimitiveHit{*hit, PrimitiveKind::sphere, id};
        }
        return std::nullopt;
    }
    const std::size_t index = id - bvh.spheres.size();
    if (const std::optional<Hit> hit = intersect_triangle(ray, bvh.triangles[index])) {
        return PrimitiveHit{*hit, PrimitiveKind::triangle, index};
    }
    return std::nullopt;
}

// The walk both queries share: nearer child first, the other on a stack, skipping every node
// that starts beyond `limit` (which `visit` may lower). visit(node) tests a leaf's primitives and
// returns true to stop.
template <class Visit>
void walk(const Bvh::Impl& bvh, const Ray& ray, double& limit, TraversalStats* stats, Visit visit) {
    if (bvh.nodes.empty()) return;
    const Vec3 inverse = 1.0 / ray.direction;
    Ray box_ray = ray;
    box_ray.t_max = limit;
    const std::optional<Interval> root = intersect_aabb(box_ray, inverse, bvh.nodes[0].box);
    if (!root) return;

    struct Pending {
        int node;
        double enter;
    };
    Pending stack[kStackSize];
    int top = 0;
    stack[top++] = {0, root->enter};
    while (top > 0) {
        const Pending current = stack[--top];
        // A nearer hit may have been found since this node was put on the stack
        if (!(current.enter <= limit)) continue;
        const Bvh::Impl::Node& node = bvh.nodes[static_cast<std::size_t>(current.node)];
        if (stats) ++stats->nodes;
        if (node.left < 0) {
            if (visit(node)) return;
            continue;
        }
        // Both children's boxes, cut at the search limit; the nearer one goes on top
        box_ray.t_max = limit;
        const std::optional<Interval> left = intersect_aabb(box_ray, inverse, bvh.nodes[static_cast<std::size_t>(node.left)].box);
        const std::optional<Interval> right = intersect_aabb(box_ray, inverse, bvh.nodes[static_cast<std::size_t>(node.right)].box);
        if (left && right) {
            const bool left_first = left->enter <= right->enter;
            const Pending near{left_first ? node.left : node.right, left_first ? left->enter : right->enter};
            const Pending far{left_first ? node.right : node.left, left_first ? right->enter : left->enter};
            stack[top++] = far;
            stack[top++] = near;
        } else if (left) {
            stack[top++] = {node.left, left->enter};
        } else if (right) {
            stack[top++] = {node.right, right->enter};
        }
    }
}

}  // namespace

Bvh::Bvh(const PrimitiveList& primitives, BvhSplit split) : impl_(std::make_unique<Impl>()) {
    Impl& bvh = *impl_;
    bvh.spheres = primitives.spheres;
    bvh.triangles = primitives.triangles;
    std::vector<Item> items;
    items.reserve(bvh.spheres.size() + bvh.triangles.size());
    for (std::size_t k = 0; k < bvh.spheres.size(); ++k) {
        const Aabb box = bounds_of(bvh.spheres[k]);
        items.push_back({box, box.center(), static_cast<std::uint32_t>(k)});
    }
    for (std::size_t k = 0; k < bvh.triangles.size(); ++k) {
        const Aabb box = bounds_of(bvh.triangles[k]);
        items.push_back({box, box.center(), static_cast<std::uint32_t>(bvh.spheres.size() + k)});
    }
    Builder(bvh, std::move(items), split).build();
}

Bvh::~Bvh() = default;
Bvh::Bvh(Bvh&&) noexcept = default;
Bvh& Bvh::operator=(Bvh&&) noexcept = default;

std::optional<PrimitiveHit> Bvh::closest_hit(const Ray& ray, TraversalStats* stats) const {
    // Each primitive is tested with t_max cut to the best t so far, as closest_hit does, and the
    // best kept by comes_before: exactly closest_hit's answer, found in another order.
    Ray nearer = ray;
    std::optional<PrimitiveHit> best;
    double limit = search_limit(ray.t_max);
    walk(*impl_, ray, limit, stats, [&](const Impl::Node& leaf) {
        for (std::uint32_t k = leaf.first; k < leaf.first + leaf.count; ++k) {
            if (stats) ++stats->primitive_tests;
            const std::optional<PrimitiveHit> hit = test_primitive(*impl_, impl_->order[k], nearer);
            if (hit && (!best || comes_before(*hit, *best))) {
                best = hit;
                nearer.t_max = hit->hit.t;
                limit = search_limit(hit->hit.t);
            }
        }
        return false;
    });
    return best;
}

bool Bvh::occluded(const Ray& ray, TraversalStats* stats) const {
    double limit = search_limit(ray.t_max);
    bool found = false;
    walk(*impl_, ray, limit, stats, [&](const Impl::Node& leaf) {
        for (std::uint32_t k = leaf.first; k < leaf.first + leaf.count; ++k) {
            if (stats) ++stats->primitive_tests;
            if (test_primitive(*impl_, impl_->order[k], ray)) return found = true;
        }
        return false;
    });
    return found;
}

std::size_t Bvh::node_count() const {
    return impl_->nodes.size();
}

std::vector<BvhNodeData> Bvh::nodes() const {
    std::vector<BvhNodeData> data;
    for (const Impl::Node& node : impl_->nodes) {
        BvhNodeData entry;
        entry.box = node.box;
        if (node.left >= 0) {
            entry.children = {static_cast<std::size_t>(node.left),
                              static_cast<std::size_t>(node.right)};
        } else {
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k)
                entry.primitives.push_back(impl_->order[k]);
        }
        data.push_back(entry);
    }
    return data;
}

}  // namespace raystep
