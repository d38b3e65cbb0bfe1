// Stage 6: rays that leave a surface. Handout: docs/stage6.md. Use your stage-1 dot here.

#include "stages/6_shading/shading.h"

#include <cmath>
#include <limits>

#include "base/errors/not_implemented.h"
#include "stages/1_vectors/vectors.h"

namespace raystep {

Ray spawn_ray(const SurfacePoint& point, const Vec3& direction, double distance,
              const RayOffset& offset) {
    // n = the geometric normal, negated when n . direction < 0 (the ray leaves by the back).
    //   along_ray:    origin = P,            t in [epsilon, distance]
    //   along_normal: origin = P + epsilon n, t in [0, distance]
    //   error_bound:  origin = P + (sum |n_i| error_i) n, then each coordinate one more ulp
    //                 away from P (std::nextafter), t in [0, distance]
    // The computed P is off the surface by rounding: starting at P, a ray can hit it at t ~ 0.
    RAYSTEP_TODO(6, "spawn_ray", "Three offset rules");
}

Ray shadow_ray(const SurfacePoint& point, const LightSample& light, const RayOffset& offset) {
    // A shadow ray asks "is anything between the point and the light?": spawn_ray towards
    // the light, as far as the light (infinity for a directional light), no farther.
    RAYSTEP_TODO(6, "shadow_ray", "Shadow rays");
}

}  // namespace raystep
