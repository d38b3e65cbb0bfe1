// Stage 4: the slab test. Handout: docs/stage4.md.

#include "stages/4_accel/aabb.h"
#include "base/errors/not_implemented.h"

namespace raystep {

std::optional<Interval> intersect_aabb(const Ray& ray, const Vec3& inverse_direction,
                                       const Aabb& box) {
    // Start from [t_min, t_max]. For each axis, the ray is between the box's two planes for
    // t between (min - A) / D and (max - A) / D (swap them when D < 0); keep the latest entry and
    // the earliest exit. Empty means a miss.
    // Three traps, all in the handout: where D = 0 and the origin lies on a plane, 0 * inf is NaN
    // (write the comparisons so that NaN changes nothing, and decide which plane comes first
    // from the sign of 1 / D, not by comparing the two t's); rounding may put a grazing ray's
    // exit just before its entry (widen the exit a little); and an empty box must miss.
    RAYSTEP_TODO(4, "intersect_aabb", "The slab test");
}

}  // namespace raystep
