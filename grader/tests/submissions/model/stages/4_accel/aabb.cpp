// Stage 4: the slab test. Handout: docs/stage4.md, "The slab test".

#include "stages/4_accel/aabb.h"

#include <cmath>
#include <utility>

namespace raystep {

std::optional<Interval> intersect_aabb(const Ray& ray, const Vec3& inverse_direction,
                                       const Aabb& box) {
    // An empty box (min +inf, max -inf) would pass every slab below
    if (box.empty()) return std::nullopt;

    double enter = ray.t_min;
    double exit = ray.t_max;
    for (int axis = 0; axis < 3; ++axis) {
        double t_near = (box.min[axis] - ray.origin[axis]) * inverse_direction[axis];
        double t_far = (box.max[axis] - ray.origin[axis]) * inverse_direction[axis];
        // Which plane comes first from the sign of 1 / D (with D = -0 it is -inf), never by
        // comparing the two t's: one of them is NaN when the origin lies on a plane and D = 0.
        if (inverse_direction[axis] < 0.0) std::swap(t_near, t_far);
        // Written so that a NaN (0 * inf) leaves the bound as it was
        enter = t_near > enter ? t_near : enter;
        exit = t_far < exit ? t_far : exit;
    }

    // Rounding can put a touching ray's exit an ulp before its entry: widen the exit by
    // 2 gamma(3) of itself, gamma(n) = n u / (1 - n u), u = 2^-53 (Ize 2013, JCGT 2(2)).
    constexpr double u = 0x1p-53;
    constexpr double gamma3 = 3.0 * u / (1.0 - 3.0 * u);
    exit += 2.0 * gamma3 * std::abs(exit);
    if (!(enter <= exit)) return std::nullopt;  // also rejects NaN
    return Interval{enter, exit};
}

}  // namespace raystep
