#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "stages/3_intersect/intersect.h"
#include "stages/4_accel/aabb.h"
#include "stages/4_accel/traversal.h"

namespace raystep {

/// How a BVH chooses where to split a node's primitives.
enum class BvhSplit {
    median,  ///< at the median of the primitives' centroids along the box's longest axis
    sah,     ///< where the surface area heuristic's estimated cost is lowest
};

/// One node of a BVH as plain data (Bvh::nodes): the grader checks a tree through these and walks
/// it with a traversal of its own, and they are what to print when a tree looks wrong.
struct BvhNodeData {
    Aabb box;  ///< holds the boxes of its children, or of its primitives in a leaf
    std::vector<std::size_t> children;    ///< indices into Bvh::nodes(); empty in a leaf
    std::vector<std::size_t> primitives;  ///< a leaf's: spheres 0 to S - 1, then triangles from S
};

/// A bounding volume hierarchy over the spheres and triangles of a PrimitiveList (planes are
/// unbounded and stay outside: test them separately). Its layout is the implementation's own
/// (Bvh::Impl, in bvh.cpp).
class Bvh {
  public:
    /// Builds over a copy of the list's spheres and triangles.
    Bvh(const PrimitiveList& primitives, BvhSplit split);
    ~Bvh();
    Bvh(Bvh&&) noexcept;
    Bvh& operator=(Bvh&&) noexcept;

    /// Exactly what closest_hit returns for the same spheres and triangles (same primitive, same
    /// t, ties broken by comes_before), found by visiting nodes front to back and stopping once no
    /// nearer node is left. Indices are into the list's spheres and triangles.
    std::optional<PrimitiveHit> closest_hit(const Ray& ray, TraversalStats* stats = nullptr) const;

    /// True when any sphere or triangle has a hit in [ray.t_min, ray.t_max]: a shadow ray's
    /// question, answered at the first hit found.
    bool occluded(const Ray& ray, TraversalStats* stats = nullptr) const;

    /// The number of nodes, for reports.
    std::size_t node_count() const;

    /// The tree as data, the root first: every node the walk visits, with the box it tests there,
    /// and every primitive in some leaf. Empty for a tree over nothing. docs/stage4.md, "Handing
    /// the structure over".
    std::vector<BvhNodeData> nodes() const;

    struct Impl;

  private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace raystep
