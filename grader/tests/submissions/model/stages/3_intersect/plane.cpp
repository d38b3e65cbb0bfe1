// Stage 3: ray-plane. Handout: docs/stage3.md, "Ray-plane".

#include <cmath>

#include "stages/1_vectors/vectors.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

std::optional<Hit> intersect_plane(const Ray& ray, const Plane& plane) {
    // t = (p0 - A) . N / (D . N); D . N = 0 is a ray parallel to the plane (or a zero D or N).
    const double denominator = dot(ray.direction, plane.normal);
    if (denominator == 0.0) return std::nullopt;
    const double t = dot(plane.point - ray.origin, plane.normal) / denominator;

    // Only t in [t_min, t_max]; written so that a NaN or infinite t is a miss too.
    if (!(t >= ray.t_min && t <= ray.t_max) || !std::isfinite(t)) return std::nullopt;
    return Hit{t, normalize(plane.normal)};
}

}  // namespace raystep
