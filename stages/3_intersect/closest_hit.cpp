// Stage 3: the closest hit over a list. Handout: docs/stage3.md.

#include "base/errors/not_implemented.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

std::optional<PrimitiveHit> closest_hit(const Ray& ray, const PrimitiveList& primitives) {
    // Test every sphere, triangle and plane and keep the hit with the smallest t. Shrinking
    // t_max to the best t so far makes every later test reject farther hits by itself.
    RAYSTEP_TODO(3, "closest_hit", "The closest hit");
}

}  // namespace raystep
