// Stage 3: ray-plane. Handout: docs/stage3.md.

#include "base/errors/not_implemented.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

std::optional<Hit> intersect_plane(const Ray& ray, const Plane& plane) {
    // Points p on the plane satisfy (p - p0) . N = 0. Put R(t) = A + t D in for p:
    //   t = (p0 - A) . N / (D . N).
    // D . N = 0 means the ray runs parallel to the plane: a miss. Keep t only inside
    // [ray.t_min, ray.t_max]. The hit's normal is N normalized.
    RAYSTEP_TODO(3, "intersect_plane", "Ray-plane");
}

}  // namespace raystep
