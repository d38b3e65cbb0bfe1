#pragma once

#include "base/math/wide_vec.h"
#include "stages/6_shading/shading.h"

namespace raystep {

// What the error-bound rule of spawn_ray (stages/6_shading/shading.h) promises about the origin
// of a ray that leaves a surface, decided in long double. Stage 6 judges spawn_ray and
// shadow_ray by it, stage 7 the mirror ray, which leaves by the same rule.

/// The geometric normal of `point` on the side a ray along `direction` leaves to; in the tangent
/// plane (or for a NaN direction), the normal as given.
WideVec leaving_normal(const SurfacePoint& point, const Vec3& direction);

/// Where an error-bound origin may be: with n the leaving normal and d = sum |n_i| error_i,
/// strictly more than d along n from the point, no more than `ulps` beyond d, and within `ulps`
/// of the line along n. `ulps` is 4 ulps of the point's largest coordinate (or of d, if larger;
/// or 4 subnormal steps, at the origin with no error):
/// rounding and the one-ulp step move the origin by that much, along n and sideways, and the
/// step's direction is not judged.
struct ErrorBoundOrigin {
    WideVec point;
    WideVec normal;
    Wide offset;
    double ulps;
};

/// The region for a ray leaving `point` along `direction`.
ErrorBoundOrigin error_bound_origin(const SurfacePoint& point, const Vec3& direction);

/// Whether `origin` is in the region. The origin and the point differ by a few ulps and d, so
/// their difference is exact in long double and its dot product with n rounds some 2^-64 of d,
/// far below the half ulp the rule's step adds. Written so that a NaN fails.
bool within(const ErrorBoundOrigin& region, const Vec3& origin);

}  // namespace raystep
