// Stage 4 reference solution: the BVH's queries.

#include "stages/4_accel/bvh.h"

#include <cmath>
#include <limits>

#include "solutions/4_accel/bvh_layout.h"
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
double search_limit(double t) { return t + kPruneSlack * std::abs(t); }

// A ray prepared for box tests: its inverse direction, computed once.
struct BoxRay {
    Vec3 origin;
    Vec3 inverse;
    double t_min;
};

bool enters(const BoxRay& ray, const float low[3], const float high[3], double limit,
            double& enter) {
    double entry = ray.t_min;
    double exit = limit;
    for (int axis = 0; axis < 3; ++axis) {
        clip_to_slab(ray.origin[axis], ray.inverse[axis], low[axis], high[axis], entry, exit);
    }
    enter = entry;
    return entry <= widen_exit(exit);
}

// The queries share one walk: nearer children first, a stack of the others, skipping any whose
// entry lies beyond the search limit. `Visit` tests a leaf's primitives and returns true to stop.
template <class Limit, class Visit>
void walk(const Bvh::Impl& bvh, const Ray& ray, TraversalStats* stats, Limit limit, Visit visit) {
    if (bvh.slots.empty()) return;
    const BoxRay box_ray{ray.origin, 1.0 / ray.direction, ray.t_min};
    {
        double entry = ray.t_min;
        double exit = ray.t_max;
        for (int axis = 0; axis < 3; ++axis) {
            clip_to_slab(ray.origin[axis], box_ray.inverse[axis], bvh.root_box.min[axis],
                         bvh.root_box.max[axis], entry, exit);
        }
        if (!(entry <= widen_exit(exit))) return;
    }

    struct Pending {
        BvhChild child;
        double enter;
    };
    Pending stack[kBvhStackSize];
    int top = 0;
    stack[top++] = {bvh.root, ray.t_min};
    std::uint64_t nodes = 0;
    while (top > 0) {
        const Pending pending = stack[--top];
        if (pending.enter > limit()) continue;
        if (pending.child.count > 0) {
            if (visit(pending.child.index, pending.child.count)) break;
            continue;
        }
        ++nodes;
        const BvhNode& node = bvh.nodes[pending.child.index];
        double enter[2];
        const bool hit0 = enters(box_ray, node.low[0], node.high[0], limit(), enter[0]);
        const bool hit1 = enters(box_ray, node.low[1], node.high[1], limit(), enter[1]);
        const BvhChild child0{node.child[0], node.count[0]};
        const BvhChild child1{node.child[1], node.count[1]};
        // Push the farther first, so the nearer is taken next.
        if (hit0 && hit1) {
            const bool first_nearer = enter[0] <= enter[1];
            stack[top++] = first_nearer ? Pending{child1, enter[1]} : Pending{child0, enter[0]};
            stack[top++] = first_nearer ? Pending{child0, enter[0]} : Pending{child1, enter[1]};
        } else if (hit0) {
            stack[top++] = {child0, enter[0]};
        } else if (hit1) {
            stack[top++] = {child1, enter[1]};
        }
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
    walk(
        *impl_, ray, stats, [&] { return search_limit(nearer.t_max); },
        [&](std::uint32_t first, std::uint32_t count) {
            for (std::uint32_t slot = first; slot < first + count; ++slot) {
                ++tests;
                const std::optional<PrimitiveHit> hit = test_slot(*impl_, slot, nearer);
                if (hit && (!best || comes_before(*hit, *best))) {
                    best = hit;
                    nearer.t_max = hit->hit.t;
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
    walk(
        *impl_, ray, stats, [&] { return search_limit(ray.t_max); },
        [&](std::uint32_t first, std::uint32_t count) {
            for (std::uint32_t slot = first; slot < first + count; ++slot) {
                ++tests;
                if (test_slot(*impl_, slot, ray)) return found = true;
            }
            return false;
        });
    if (stats) stats->primitive_tests += tests;
    return found;
}

std::size_t Bvh::node_count() const { return impl_->nodes.size(); }

}  // namespace raystep
