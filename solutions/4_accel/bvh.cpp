// Stage 4 reference solution: the BVH's queries.

#include "stages/4_accel/bvh.h"

#include <cmath>
#include <limits>

#include "solutions/4_accel/bvh_layout.h"
#include "solutions/4_accel/node_test.h"
#include "solutions/4_accel/slab_test.h"

namespace raystep {

namespace {

// Children whose boxes the ray enters no more than this much (relative) beyond the best hit so
// far are still visited. A primitive's t and its box's entry are rounded separately, so a hit
// can come out a few ulps before the box that holds it is entered; skipping such a box could
// lose a hit that closest_hit, testing every primitive, finds. 2^-40 is a thousand times those
// roundings, and costs nothing measurable.
constexpr double kPruneSlack = 0x1p-40;

// The far end of the search: the best hit so far (or t_max), widened by the slack.
double search_limit(double t) {
    return t + kPruneSlack * std::abs(t);
}

// The queries share one walk: nearer children first, a stack of the others, skipping any whose
// entry lies beyond `bound`, the float search limit. `Visit` tests a leaf's primitives, may lower
// the bound (after a nearer hit), and returns true to stop.
//
// The node test (node_test.h) takes all four children at once, and the stack is a plain array,
// never initialized: this loop is where the time goes (`raystep bench`, docs/stage4.md,
// "Measured on the development machine").
template <class Visit>
void walk(const Bvh::Impl& bvh, const Ray& ray, TraversalStats* stats, Visit visit) {
    if (bvh.slots.empty()) return;
    {
        const Vec3 inverse = 1.0 / ray.direction;
        double entry = ray.t_min;
        double exit = ray.t_max;
        for (int axis = 0; axis < 3; ++axis) {
            clip_to_slab(ray.origin[axis], inverse[axis], bvh.root_box.min[axis],
                         bvh.root_box.max[axis], entry, exit);
        }
        if (!(entry <= widen_exit(exit))) return;
    }
    const NodeRay node_ray(ray);
    const ChildTest child_test(node_ray);
    float bound = rounded_up(search_limit(ray.t_max));

    // The node at hand stays in `current`; the other children it enters wait on the stack,
    // farthest deepest, so the nearest comes next.
    struct Pending {
        std::uint32_t index;
        std::uint32_t count;  ///< 0: an inner node
        float enter;
    };
    Pending stack[kBvhStackSize];
    int top = 0;
    Pending current{bvh.root.index, bvh.root.count, node_ray.t_min};
    // The next node from the stack, skipping what starts beyond the best hit found since it
    // waited; false when none is left.
    const auto next = [&] {
        while (top > 0) {
            current = stack[--top];
            if (current.enter <= bound) return true;
        }
        return false;
    };
    std::uint64_t nodes = 0;
    for (;;) {
        if (current.count > 0) {
            if (visit(current.index, current.count, bound)) break;
            if (!next()) break;
            continue;
        }
        ++nodes;
        const BvhNode& node = bvh.nodes[current.index];
        float entry[BvhNode::kWidth];
        const int hits = child_test.enter_children(node, bound, entry);
        if (hits == 0) {
            if (!next()) break;
            continue;
        }
        // The children entered go on the stack sorted by entry, farthest deepest (insertion
        // sort of at most four), and the nearest comes straight back off it.
        const int base = top;
        for (int c = 0; c < BvhNode::kWidth; ++c) {
            if ((hits >> c & 1) == 0) continue;
            const Pending child{node.child[c], node.count[c], entry[c]};
            int k = top++;
            while (k > base && stack[k - 1].enter < child.enter) {
                stack[k] = stack[k - 1];
                --k;
            }
            stack[k] = child;
        }
        current = stack[--top];
    }
    if (stats) stats->nodes += nodes;
}

// The hit of the primitive in a slot, with the ray cut at t_max.
std::optional<PrimitiveHit> test_slot(const Bvh::Impl& bvh, std::uint32_t slot, const Ray& ray) {
    const std::uint32_t id = bvh.slots[slot];
    if (id < bvh.sphere_count) {
        const std::optional<Hit> hit = intersect_sphere(ray, bvh.spheres[id]);
        if (hit) return PrimitiveHit{*hit, PrimitiveKind::sphere, id};
        return std::nullopt;
    }
    const std::optional<Hit> hit = intersect_triangle(ray, bvh.slot_triangles[slot]);
    if (hit) return PrimitiveHit{*hit, PrimitiveKind::triangle, id - bvh.sphere_count};
    return std::nullopt;
}

}  // namespace

Bvh::Bvh(const PrimitiveList& primitives, BvhSplit split) : impl_(std::make_unique<Impl>()) {
    build_bvh(*impl_, primitives, split);
}

Bvh::~Bvh() = default;
Bvh::Bvh(Bvh&&) noexcept = default;
Bvh& Bvh::operator=(Bvh&&) noexcept = default;

std::optional<PrimitiveHit> Bvh::closest_hit(const Ray& ray, TraversalStats* stats) const {
    // Every primitive is tested with t_max the best t so far, as closest_hit does, and the best
    // kept by comes_before: the same answer, found in another order.
    Ray nearer = ray;
    std::optional<PrimitiveHit> best;
    std::uint64_t tests = 0;
    walk(*impl_, ray, stats, [&](std::uint32_t first, std::uint32_t count, float& bound) {
        for (std::uint32_t slot = first; slot < first + count; ++slot) {
            ++tests;
            const std::optional<PrimitiveHit> hit = test_slot(*impl_, slot, nearer);
            if (hit && (!best || comes_before(*hit, *best))) {
                best = hit;
                nearer.t_max = hit->hit.t;
                bound = rounded_up(search_limit(nearer.t_max));
            }
        }
        return false;
    });
    if (stats) stats->primitive_tests += tests;
    return best;
}

bool Bvh::occluded(const Ray& ray, TraversalStats* stats) const {
    bool found = false;
    std::uint64_t tests = 0;
    walk(*impl_, ray, stats, [&](std::uint32_t first, std::uint32_t count, float&) {
        for (std::uint32_t slot = first; slot < first + count; ++slot) {
            ++tests;
            if (test_slot(*impl_, slot, ray)) return found = true;
        }
        return false;
    });
    if (stats) stats->primitive_tests += tests;
    return found;
}

std::size_t Bvh::node_count() const {
    return impl_->nodes.size();
}

}  // namespace raystep
