// Stage 3: ray-sphere. Handout: docs/stage3.md.

#include "base/errors/not_implemented.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

std::optional<Hit> intersect_sphere(const Ray& ray, const Sphere& sphere) {
    // Substitute R(t) = A + t D into |p - C|^2 = r^2: with f = A - C,
    //   a t^2 + 2 b t + c = 0,  a = D . D,  b = D . f,  c = f . f - r^2.
    // Compute the discriminant b^2 - a c as a (r^2 - |f - (b / a) D|^2), r^2 minus the squared
    // distance from C to the ray's line. Solve in the stable form: q = -(b + sign(b) sqrt(disc)),
    // roots c / q and q / a (never subtract two nearly equal numbers). Return the smaller root in
    // [t_min, t_max], else the larger; the normal is (P - C) / r.
    RAYSTEP_TODO(3, "intersect_sphere", "Ray-sphere");
}

}  // namespace raystep
