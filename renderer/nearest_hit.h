#pragma once

#include <optional>

#include "stages/2_rays/ray.h"
#include "stages/4_accel/traversal.h"

namespace raystep {

// The two steps of every search for the nearest hit outside stage 4's own structures (the world's
// primitives beside its BVH, the instances, the instance BVH's leaves): keep a candidate when
// closest_hit would have picked it, and cut the ray at the best hit so far.

/// `candidate` replaces `best` when closest_hit would have picked it (comes_before).
inline void keep_nearer(std::optional<PrimitiveHit>& best,
                        const std::optional<PrimitiveHit>& candidate) {
    if (candidate && (!best || comes_before(*candidate, *best))) best = candidate;
}

/// The ray cut at the best hit so far: nothing beyond it can win.
inline Ray cut_at(const Ray& ray, const std::optional<PrimitiveHit>& best) {
    Ray cut = ray;
    if (best) cut.t_max = best->hit.t;
    return cut;
}

}  // namespace raystep
