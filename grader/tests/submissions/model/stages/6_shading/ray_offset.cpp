// Stage 6: rays that leave a surface. Handout: docs/stage6.md, "Three offset rules".

#include "stages/6_shading/shading.h"

#include <cmath>
#include <limits>

#include "stages/1_vectors/vectors.h"

namespace raystep {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The geometric normal on the side the ray leaves to; as given when the ray runs along the
// surface (n . direction = 0).
Vec3 leaving_normal(const SurfacePoint& point, const Vec3& direction) {
    return dot(point.normal, direction) < 0.0 ? -point.normal : point.normal;
}

// The error-bound rule (pbrt-v4, OffsetRayOrigin): the exact point is within position +- error,
// so at most d = sum |n_i| error_i along n from position. Start d along n, then one more ulp
// away in each coordinate, since the addition may round back towards the surface.
Vec3 error_bound_origin(const SurfacePoint& point, const Vec3& n) {
    const double d = std::abs(n.x) * point.error.x + std::abs(n.y) * point.error.y +
                     std::abs(n.z) * point.error.z;
    Vec3 origin = point.position + d * n;
    for (int i = 0; i < 3; ++i) {
        if (n[i] > 0.0) {
            origin[i] = std::nextafter(origin[i], kInfinity);
        } else if (n[i] < 0.0) {
            origin[i] = std::nextafter(origin[i], -kInfinity);
        }
    }
    return origin;
}

}  // namespace

Ray spawn_ray(const SurfacePoint& point, const Vec3& direction, double distance,
              const RayOffset& offset) {
    const Vec3 n = leaving_normal(point, direction);
    switch (offset.rule) {
        case OffsetRule::along_ray:
            return Ray{point.position, direction, offset.epsilon, distance};
        case OffsetRule::along_normal:
            return Ray{point.position + offset.epsilon * n, direction, 0.0, distance};
        case OffsetRule::error_bound:
            break;
    }
    return Ray{error_bound_origin(point, n), direction, 0.0, distance};
}

Ray shadow_ray(const SurfacePoint& point, const LightSample& light, const RayOffset& offset) {
    // As far as the light and no farther (infinity for a directional light)
    return spawn_ray(point, light.direction, light.distance, offset);
}

}  // namespace raystep
