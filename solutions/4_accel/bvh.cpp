// Stage 4 reference solution: the BVH's queries.

#include "stages/4_accel/bvh.h"

#include <cmath>
#include <limits>
#include <optional>
#include <utility>

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

// Where the ray leaves the scene's box, clipped to [t_min, t_max] in double, widened so that it is
// never before the exact exit; nullopt when the ray misses the box in that range: a ray that
// misses everything costs this and nothing more. The clip is at t_max widened by the slack, as
// the pruning is: a shadow ray ends exactly at the t of the surface it aims at, and that
// primitive's box can be entered a few ulps after its own t.
inline std::optional<double> root_exit(const Bvh::Impl& bvh, const Ray& ray, const Vec3& inverse) {
    double entry = ray.t_min;
    double exit = search_limit(ray.t_max);
    for (int axis = 0; axis < 3; ++axis) {
        clip_to_slab(ray.origin[axis], inverse[axis], bvh.root_box.min[axis],
                     bvh.root_box.max[axis], entry, exit);
    }
    exit = widen_exit(exit);
    if (!(entry <= exit)) return std::nullopt;
    return exit;
}

// A node or leaf waiting to be visited, and where the ray enters its box.
struct Pending {
    std::uint32_t index;
    std::uint32_t count;  ///< 0: an inner node
    float enter;
};
static_assert(sizeof(Pending) * kBvhStackSize <= 8192,
              "the walk's stack array takes at most 8 KiB of the thread's stack");

// The lowest bit set in `bits` (at least one is). GCC and Clang count trailing zeros in one
// instruction; elsewhere a loop, since C++17 has no portable count. The count sits on the walk's
// critical path, between the node test and the next node's address, which is why it is not a
// table load: the count ran the bunny's primary rays faster (`raystep-reference bench --workload
// bunny --threads 1`; docs/measurements/stage4-bench.md, "The walk").
inline int lowest_bit(unsigned bits) {
#if defined(__GNUC__)
    return __builtin_ctz(bits);
#else
    int bit = 0;
    while ((bits & 1u) == 0) {
        bits >>= 1;
        ++bit;
    }
    return bit;
#endif
}

// The lowest child in `hits`, entered at its entry.
Pending lowest_child(const BvhNode& node, unsigned hits, const float entry[BvhNode::kWidth]) {
    const int c = lowest_bit(hits);
    return {node.child[c], node.count[c], entry[c]};
}

// Asks the memory system for what a child holds (the first half of its node, or its leaf's first
// triangles) when it goes on the stack, so the read overlaps the nearer subtree's work instead of
// stalling when the child comes off. On incoherent rays most of the tree is out of the
// first-level cache, and this is a read the walk would otherwise wait for; two lines, because
// asking for all four of an eight-wide node was no faster (`raystep-reference bench --workload
// bunny --threads 1` re-measures both). A prefetch is only a hint: it cannot fault, and changes
// no result.
inline void prefetch(const Bvh::Impl& bvh, const Pending& child) {
#ifdef RAYSTEP_BVH_SSE2
    const char* at = child.count == 0
                         ? reinterpret_cast<const char*>(bvh.nodes.data() + child.index)
                         : reinterpret_cast<const char*>(bvh.slot_triangles.data() + child.index);
    _mm_prefetch(at, _MM_HINT_T0);
    _mm_prefetch(at + 64, _MM_HINT_T0);
#else
    static_cast<void>(bvh);
    static_cast<void>(child);
#endif
}

// Of the children the ray enters (the set bits of `hits`, at least one), returns the nearest, to
// visit next, and pushes the others onto the stack above `top`, farthest deepest. A ray mostly
// enters one child or two, which take no loop and at most one comparison; only three or more
// are sorted (insertion sort). It runs fewer instructions than pushing every child and popping
// the nearest, though not measurably less time: the branches that remain depend on the ray and
// are mispredicted about as often as those they replace (`valgrind --tool=callgrind
// raystep-reference bench --quick --workload bunny-primary --threads 1` counts them).
inline Pending nearest_child(const Bvh::Impl& bvh, const BvhNode& node, unsigned hits,
                             const float entry[BvhNode::kWidth], Pending* stack, int& top) {
    Pending near = lowest_child(node, hits, entry);
    hits &= hits - 1;
    if (hits == 0) return near;
    Pending far = lowest_child(node, hits, entry);
    hits &= hits - 1;
    if (far.enter < near.enter) std::swap(near, far);
    const int base = top;
    prefetch(bvh, far);
    stack[top++] = far;
    for (; hits != 0; hits &= hits - 1) {
        Pending child = lowest_child(node, hits, entry);
        if (child.enter < near.enter) std::swap(child, near);
        prefetch(bvh, child);
        int k = top++;
        while (k > base && stack[k - 1].enter < child.enter) {
            stack[k] = stack[k - 1];
            --k;
        }
        stack[k] = child;
    }
    return near;
}

// The queries share one walk: nearer children first, a stack of the others, skipping any whose
// entry lies beyond `bound`, the float search limit. `Visit` tests a leaf's primitives, may lower
// the bound (after a nearer hit), and returns true to stop.
//
// The node test (node_test.h) takes all eight children at once, and the stack is a plain array,
// never initialized: this loop is where a query's time goes (`raystep-reference bench --workload
// bunny --threads 1` times it).
template <class Visit>
void walk(const Bvh::Impl& bvh, const Ray& ray, TraversalStats* stats, Visit visit) {
    if (bvh.slots.empty()) return;
    // 1 / D once, in double, for both the root box and the node ray
    const Vec3 inverse = 1.0 / ray.direction;
    const std::optional<double> exit = root_exit(bvh, ray, inverse);
    if (!exit) return;
    const NodeRay node_ray(ray, inverse, bvh.plane_magnitude, *exit);
    float bound = rounded_up(search_limit(ray.t_max));
    if (!node_ray.fits_float) {
        // Too large or too small for the float node test (node_test.h): every primitive.
        visit(0, static_cast<std::uint32_t>(bvh.slots.size()), bound);
        return;
    }
    const ChildTest child_test(node_ray);

    // The node at hand stays in `current`; the other children it enters wait on the stack,
    // farthest deepest, so the nearest comes next.
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
        } else {
            ++nodes;
            const BvhNode& node = bvh.nodes[current.index];
            float entry[BvhNode::kWidth];
            const int hits = child_test.enter_children(node, bound, entry);
            if (hits != 0) {
                current = nearest_child(bvh, node, static_cast<unsigned>(hits), entry, stack, top);
                continue;
            }
        }
        if (!next()) break;
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

namespace {

// Appends `child`, whose box is `box`, and everything below it to `out`; returns its index there.
// A leaf of the wide tree is a child entry, not a node, and becomes a node of its own here.
std::size_t append_node_data(const Bvh::Impl& bvh, const BvhChild& child, const Aabb& box,
                             std::vector<BvhNodeData>& out) {
    const std::size_t index = out.size();
    out.push_back({box, {}, {}});
    if (child.count > 0) {
        for (std::uint32_t slot = child.index; slot < child.index + child.count; ++slot)
            out[index].primitives.push_back(bvh.slots[slot]);
        return index;
    }
    const BvhNode& node = bvh.nodes[child.index];
    for (int c = 0; c < BvhNode::kWidth; ++c) {
        const Aabb child_box{Vec3(node.planes[0][c], node.planes[2][c], node.planes[4][c]),
                             Vec3(node.planes[1][c], node.planes[3][c], node.planes[5][c])};
        if (child_box.empty()) continue;  // an unused child
        const std::size_t appended =
            append_node_data(bvh, {node.child[c], node.count[c]}, child_box, out);
        out[index].children.push_back(appended);
    }
    return index;
}

}  // namespace

std::vector<BvhNodeData> Bvh::nodes() const {
    std::vector<BvhNodeData> data;
    if (impl_->slots.empty()) return data;
    append_node_data(*impl_, impl_->root, impl_->root_box, data);
    // The root's box is kept in double and its children's in float, rounded outward, which can
    // reach an ulp of float past it: the root handed over holds them too
    for (const std::size_t child : data[0].children)
        data[0].box.add(data[child].box);
    return data;
}

}  // namespace raystep
