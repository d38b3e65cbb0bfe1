// Stage 4 reference solution: the slab test.

#include "stages/4_accel/aabb.h"

#include <cmath>
#include <utility>

#include "solutions/4_accel/slab_test.h"

namespace raystep {

std::optional<Interval> intersect_aabb(const Ray& ray, const Vec3& inverse_direction,
                                       const Aabb& box) {
    // An empty box's inverted bounds (+inf, -inf) would pass every slab.
    if (box.empty()) return std::nullopt;
    double enter = ray.t_min;
    double exit = ray.t_max;
    for (int axis = 0; axis < 3; ++axis) {
        clip_to_slab(ray.origin[axis], inverse_direction[axis], box.min[axis], box.max[axis], enter,
                     exit);
    }
    exit = widen_exit(exit);
    if (!(enter <= exit)) return std::nullopt;  // also a NaN from an empty box
    return Interval{enter, exit};
}

}  // namespace raystep
