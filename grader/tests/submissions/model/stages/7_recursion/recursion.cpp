// Stage 7: recursive reflection. Handout: docs/stage7.md.

#include "stages/7_recursion/recursion.h"

#include <limits>

#include "stages/1_vectors/vectors.h"

namespace raystep {

Ray reflected_ray(const SurfacePoint& point, const RayOffset& offset) {
    // The ray came in along -V; the mirror sends it on along reflect(-V, N), N the shading
    // normal. reflect keeps |V|, which is 1 only up to rounding: normalize.
    const Vec3 direction = normalize(reflect(-point.to_eye, point.shading_normal));
    return spawn_ray(point, direction, std::numeric_limits<double>::infinity(), offset);
}

Color radiance(const ShadeFunction& shade, const Ray& ray, int bounces_left,
               const RayOffset& offset) {
    const std::optional<ShadedHit> hit = shade(ray);
    if (!hit) return Color(0.0);  // the ray leaves the scene

    // No bounce left, or a black mirror: the reflected ray would add nothing, do not trace it
    if (bounces_left <= 0 || hit->reflectance == Color(0.0)) return hit->local;
    const Color reflected = radiance(shade, reflected_ray(hit->point, offset), bounces_left - 1, offset);
    return hit->local + hit->reflectance * reflected;
}

}  // namespace raystep
