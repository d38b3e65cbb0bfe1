// Stage 6 reference solution: rays that leave a surface.

#include "stages/6_shading/shading.h"

#include <cmath>
#include <limits>

#include <glm/common.hpp>

#include "stages/1_vectors/vectors.h"

namespace raystep {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The geometric normal on the side a ray along `direction` leaves to. A ray in the tangent plane
// (n . direction = 0) keeps the normal as given; so does a NaN direction, which no rule can save.
Vec3 leaving_side_normal(const SurfacePoint& point, const Vec3& direction) {
    return dot(point.normal, direction) < 0.0 ? -point.normal : point.normal;
}

// The error-bound rule (Wächter and Binder, "A Fast and Robust Method for Avoiding
// Self-Intersection", Ray Tracing Gems ch. 6, 2019; pbrt-v4, OffsetRayOrigin).
//
// Why it is right: the exact hit point p lies in the box position +- error. Over that box,
// n . (p - position) is at most d = sum |n_i| error_i, so every candidate for p lies on or
// behind the plane n . x = n . position + d, and an origin strictly beyond that plane is strictly
// on the leaving side of the surface at p (the surface is flat at the scale of `error`). The sum
// position + d n rounds, possibly back towards the surface by half an ulp per coordinate; one
// more ulp away, by the sign of each n_i != 0, puts those coordinates strictly beyond the exact
// sum, so n . (origin - position) > d. Nothing here is tuned: the offset is the point's own
// rounding error, so it follows the scene's scale by itself.
//
// The ulp step follows the sign of n_i, which is that of the offset wherever the offset is not
// zero, as in pbrt-v4. Where it is zero (an exact point, error 0, such as (x, 0, z) on the plane
// y = 0) pbrt-v4 would not move at all and the ray would start on the surface with t_min = 0;
// the step along the normal's signs still takes it off.
Vec3 error_bound_origin(const SurfacePoint& point, const Vec3& n) {
    const double d = dot(glm::abs(n), point.error);
    Vec3 origin = point.position + d * n;
    for (int i = 0; i < 3; ++i) {
        if (n[i] > 0.0) {
            origin[i] = std::nextafter(origin[i], kInf);
        } else if (n[i] < 0.0) {
            origin[i] = std::nextafter(origin[i], -kInf);
        }
    }
    return origin;
}

}  // namespace

Ray spawn_ray(const SurfacePoint& point, const Vec3& direction, double distance,
              const RayOffset& offset) {
    switch (offset.rule) {
        case OffsetRule::along_ray:
            return {point.position, direction, offset.epsilon, distance};
        case OffsetRule::along_normal:
            return {point.position + offset.epsilon * leaving_side_normal(point, direction),
                    direction, 0.0, distance};
        case OffsetRule::error_bound:
            break;
    }
    // error_bound, the default rule
    return {error_bound_origin(point, leaving_side_normal(point, direction)), direction, 0.0,
            distance};
}

Ray shadow_ray(const SurfacePoint& point, const LightSample& light, const RayOffset& offset) {
    return spawn_ray(point, light.direction, light.distance, offset);
}

}  // namespace raystep
