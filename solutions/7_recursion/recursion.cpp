// Stage 7 reference solution: recursive reflection.

#include "stages/7_recursion/recursion.h"

#include <limits>

#include "stages/1_vectors/vectors.h"

namespace raystep {

Ray reflected_ray(const SurfacePoint& point, const RayOffset& offset) {
    // reflect keeps the length of -V, which is 1 only up to rounding: normalized, t along the
    // reflected ray is a distance, as on every other ray.
    const Vec3 direction = normalize(reflect(-point.to_eye, point.shading_normal));
    return spawn_ray(point, direction, std::numeric_limits<double>::infinity(), offset);
}

Color radiance(const ShadeFunction& shade, const Ray& ray, int bounces_left,
               const RayOffset& offset) {
    const std::optional<ShadedHit> hit = shade(ray);
    if (!hit) return Color(0.0);

    // The mirror's share, only when it can add something: a black reflectance or no bounce left
    // would trace a whole ray (a BVH walk and its shadow rays) for nothing.
    if (bounces_left <= 0 || hit->reflectance == Color(0.0)) return hit->local;
    return hit->local + hit->reflectance * radiance(shade, reflected_ray(hit->point, offset),
                                                    bounces_left - 1, offset);
}

}  // namespace raystep
