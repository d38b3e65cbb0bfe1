#pragma once

#include <cstdint>
#include <optional>

#include "stages/3_intersect/intersect.h"

namespace raystep {

/// What a query through an acceleration structure cost, added up over the queries it is given
/// to: the teaching numbers of stage 4 (and the renderer's cost view).
struct TraversalStats {
    std::uint64_t nodes = 0;            ///< BVH nodes or grid cells visited
    std::uint64_t primitive_tests = 0;  ///< sphere and triangle tests run
};

/// True when hit `a` comes before hit `b` in closest_hit's order: the smaller t, and on equal t
/// the earlier primitive (spheres before triangles, then by index). Acceleration structures find
/// hits in another order than a list does; comparing this way, they still return exactly the
/// hit closest_hit returns.
inline bool comes_before(const PrimitiveHit& a, const PrimitiveHit& b) {
    if (a.hit.t != b.hit.t) return a.hit.t < b.hit.t;
    if (a.kind != b.kind) return a.kind < b.kind;
    return a.index < b.index;
}

}  // namespace raystep
