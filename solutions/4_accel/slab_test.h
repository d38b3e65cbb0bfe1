#pragma once

// The slab test's two steps, shared by intersect_aabb and the BVH's inner loop.

#include <cmath>
#include <utility>

namespace raystep {

/// Narrows [enter, exit] to where the ray is between the planes x = low and x = high of one axis
/// (Kay and Kajiya 1986). Where the direction component is 0, the inverse is infinite: an origin
/// strictly between the planes gives -inf and +inf and narrows nothing, one outside gives two
/// infinities of one sign and empties the interval. An origin exactly on a plane gives
/// 0 * inf = NaN, and each comparison is written so that NaN leaves the bound as it was: the ray
/// runs inside the plane, which the closed slab contains. Which plane is entered first comes from
/// the inverse's sign, not from comparing the two t's, which a NaN would decide wrongly (with
/// D = -0, the inverse is -inf and the far plane's t is -inf).
inline void clip_to_slab(double origin, double inverse, double low, double high, double& enter,
                         double& exit) {
    double t_near = (low - origin) * inverse;
    double t_far = (high - origin) * inverse;
    if (inverse < 0.0) std::swap(t_near, t_far);
    enter = t_near > enter ? t_near : enter;
    exit = t_far < exit ? t_far : exit;
}

/// Rounding in (bound - origin) * inverse can put a touching ray's exit a hair before its entry.
/// Widening the exit by 2 gamma(3) of itself, gamma(n) = n u / (1 - n u) with u = 2^-53, covers
/// the rounding of the three operations that made it (Ize 2013, "Robust BVH Ray Traversal",
/// JCGT 2(2)), so a ray that touches a box is never said to miss it.
inline double widen_exit(double exit) {
    constexpr double u = 0x1p-53;
    constexpr double gamma3 = 3.0 * u / (1.0 - 3.0 * u);
    return exit + 2.0 * gamma3 * std::abs(exit);
}

}  // namespace raystep
