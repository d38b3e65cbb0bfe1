#include "renderer/instance_bvh.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "renderer/nearest_hit.h"

namespace raystep {

namespace {

// Instances per leaf: each costs a matrix-vector product and a bottom-level query, so a leaf
// holds as few as the median split leaves.
constexpr std::uint32_t kLeafInstances = 2;

// A median split halves every node, so the tree is at most 33 levels deep for 2^32 instances, and
// a stack of the nodes still to visit never holds more than one per level plus one.
constexpr std::size_t kStackSize = 64;

struct Pending {
    std::uint32_t node;
    double enter;
};

}  // namespace

InstanceBvh::InstanceBvh(const std::vector<Instance>& instances) {
    // Instances with nothing in them (a mesh of no faces) have an empty box and stay out.
    for (std::uint32_t k = 0; k < instances.size(); ++k) {
        if (!instances[k].world_bounds.empty()) order_.push_back(k);
    }
    if (order_.empty()) return;
    nodes_.reserve(2 * order_.size() + 1);
    nodes_.emplace_back();
    build_node(instances, 0, 0, static_cast<std::uint32_t>(order_.size()));
}

void InstanceBvh::build_node(const std::vector<Instance>& instances, std::uint32_t node,
                             std::uint32_t begin, std::uint32_t end) {
    Aabb box;
    Aabb centres;
    for (std::uint32_t k = begin; k < end; ++k) {
        box.add(instances[order_[k]].world_bounds);
        centres.add(instances[order_[k]].world_bounds.center());
    }
    nodes_[node].box = box;
    if (end - begin <= kLeafInstances) {
        nodes_[node].first = begin;
        nodes_[node].count = end - begin;
        return;
    }
    const Vec3 extent = centres.extent();
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t middle = begin + (end - begin) / 2;
    // A box reaching to infinity on both sides (coordinates that overflowed) has a NaN centre:
    // ordered as 0, so that the order stays strict and weak.
    const auto centre = [&](std::uint32_t k) {
        const double c = instances[k].world_bounds.center()[axis];
        return std::isnan(c) ? 0.0 : c;
    };
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) { return centre(a) < centre(b); });
    const auto left = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    nodes_.emplace_back();
    nodes_[node].first = left;
    nodes_[node].count = 0;
    build_node(instances, left, begin, middle);
    build_node(instances, left + 1, middle, end);
}

std::optional<PrimitiveHit> InstanceBvh::closest_hit(
    const std::vector<Instance>& instances, const std::vector<InstanceGeometry>& geometries,
    const Ray& ray, TraversalStats* stats) const {
    std::optional<PrimitiveHit> best;
    if (nodes_.empty()) return best;
    const Vec3 inverse = 1.0 / ray.direction;
    const std::optional<Interval> root = intersect_aabb(ray, inverse, nodes_[0].box);
    if (!root) return best;
    std::array<Pending, kStackSize> stack;
    std::size_t size = 0;
    stack[size++] = {0, root->enter};
    while (size > 0) {
        const Pending pending = stack[--size];
        if (best && pending.enter > best->hit.t) continue;
        if (stats) ++stats->nodes;
        const Node& node = nodes_[pending.node];
        if (node.count > 0) {
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
                const Instance& instance = instances[order_[k]];
                keep_nearer(best, instance_closest_hit(instance, geometries[instance.geometry],
                                                       cut_at(ray, best), stats));
            }
            continue;
        }
        const Ray cut = cut_at(ray, best);
        const std::optional<Interval> left = intersect_aabb(cut, inverse, nodes_[node.first].box);
        const std::optional<Interval> right =
            intersect_aabb(cut, inverse, nodes_[node.first + 1].box);
        // The farther child goes on the stack first, so the nearer is visited first.
        if (left && right) {
            const bool left_first = left->enter <= right->enter;
            stack[size++] = left_first ? Pending{node.first + 1, right->enter}
                                       : Pending{node.first, left->enter};
            stack[size++] = left_first ? Pending{node.first, left->enter}
                                       : Pending{node.first + 1, right->enter};
        } else if (left) {
            stack[size++] = {node.first, left->enter};
        } else if (right) {
            stack[size++] = {node.first + 1, right->enter};
        }
    }
    return best;
}

bool InstanceBvh::occluded(const std::vector<Instance>& instances,
                           const std::vector<InstanceGeometry>& geometries, const Ray& ray) const {
    if (nodes_.empty()) return false;
    const Vec3 inverse = 1.0 / ray.direction;
    std::array<std::uint32_t, kStackSize> stack;
    std::size_t size = 0;
    stack[size++] = 0;
    while (size > 0) {
        const Node& node = nodes_[stack[--size]];
        if (!intersect_aabb(ray, inverse, node.box)) continue;
        if (node.count == 0) {
            stack[size++] = node.first;
            stack[size++] = node.first + 1;
            continue;
        }
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
            const Instance& instance = instances[order_[k]];
            if (instance_occluded(instance, geometries[instance.geometry], ray)) return true;
        }
    }
    return false;
}

}  // namespace raystep
