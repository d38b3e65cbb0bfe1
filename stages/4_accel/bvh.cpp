// Stage 4: the bounding volume hierarchy. Handout: docs/stage4.md.

#include "stages/4_accel/bvh.h"

#include <vector>

#include "base/errors/not_implemented.h"

namespace raystep {

// Your tree. The lecture's layout is a flat array of nodes: each has a box and either two
// children (indices into the array) or a range of primitives (a leaf). Keep your own copy of
// the spheres and triangles, and number them as closest_hit does: spheres first, then triangles.
struct Bvh::Impl {
    struct Node {
        Aabb box;
        int children[2] = {-1, -1};  ///< -1, -1 for a leaf
        std::size_t first = 0;       ///< a leaf's primitives: order[first .. first + count)
        std::size_t count = 0;
    };
    std::vector<Node> nodes;
    std::vector<std::size_t> order;  ///< primitive numbers in leaf order
    std::vector<Sphere> spheres;
    std::vector<Triangle> triangles;
};

Bvh::Bvh(const PrimitiveList& primitives, BvhSplit split) : impl_(std::make_unique<Impl>()) {
    // Build top down from all primitives: a node's box contains its primitives' boxes
    // (bounds_of); split them in two and build each half, until a node holds a handful.
    //   median: sort by centroid along the box's longest axis and cut in the middle.
    //   sah:    try cuts along each axis and keep the one with the lowest estimated cost,
    //           C = C_node + C_test (A_left N_left + A_right N_right) / A_parent,
    //           or make a leaf when no cut beats testing every primitive.
    RAYSTEP_TODO(4, "Bvh::Bvh", "Building a BVH");
}

Bvh::~Bvh() = default;
Bvh::Bvh(Bvh&&) noexcept = default;
Bvh& Bvh::operator=(Bvh&&) noexcept = default;

std::optional<PrimitiveHit> Bvh::closest_hit(const Ray& ray, TraversalStats* stats) const {
    // From the root: test both children's boxes with intersect_aabb, visit the nearer first and
    // keep the other on a stack; skip a box that starts beyond the best hit so far. In a leaf,
    // test each primitive with the stage-3 functions and keep the best by comes_before, so the
    // answer is exactly closest_hit's. Count nodes and tests in *stats when it is given.
    RAYSTEP_TODO(4, "Bvh::closest_hit", "Walking a BVH");
}

bool Bvh::occluded(const Ray& ray, TraversalStats* stats) const {
    // The same walk, stopping at the first hit in range: a shadow ray needs no nearest.
    RAYSTEP_TODO(4, "Bvh::occluded", "Shadow rays need any hit");
}

std::size_t Bvh::node_count() const {
    RAYSTEP_TODO(4, "Bvh::node_count", "Building a BVH");
}

std::vector<BvhNodeData> Bvh::nodes() const {
    // Your nodes as the grader reads them, root first: each one's box, and its children's indices
    // into this list (an inner node) or its primitives' numbers (a leaf), spheres first, then
    // triangles, as closest_hit numbers them. With the flat array above, node k becomes entry k.
    RAYSTEP_TODO(4, "Bvh::nodes", "Handing the structure over");
}

}  // namespace raystep
