#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/instance.h"

namespace raystep {

/// The top level of a two-level BVH: a binary tree over the instances' world boxes, each leaf a
/// few instances, each instance holding its own BVH (the bottom level) in its own frame. Boxes
/// are tested by stage 4's slab test. Built by splitting at the median of the boxes' centres
/// along the longest axis: instances are few next to triangles, so the build is cheap whatever
/// the split, and a median keeps the tree balanced for the evenly spread placements a scene file
/// writes.
class InstanceBvh {
  public:
    explicit InstanceBvh(const std::vector<Instance>& instances);

    /// Exactly what testing every instance in turn returns: the hit that comes first by
    /// comes_before, visiting boxes front to back and cutting the ray at the best hit so far.
    std::optional<PrimitiveHit> closest_hit(const std::vector<Instance>& instances,
                                            const std::vector<InstanceGeometry>& geometries,
                                            const Ray& ray, TraversalStats* stats) const;

    /// True when any instance has a hit within [ray.t_min, ray.t_max].
    bool occluded(const std::vector<Instance>& instances,
                  const std::vector<InstanceGeometry>& geometries, const Ray& ray) const;

    std::size_t node_count() const { return nodes_.size(); }

  private:
    struct Node {
        Aabb box;
        std::uint32_t first = 0;  ///< a leaf's first entry of order_; an inner node's left child
        std::uint32_t count = 0;  ///< a leaf's number of instances; 0 for an inner node
    };

    void build_node(const std::vector<Instance>& instances, std::uint32_t node, std::uint32_t begin,
                    std::uint32_t end);

    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;  ///< instance indices, each leaf's contiguous
};

}  // namespace raystep
