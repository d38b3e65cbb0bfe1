#pragma once

#include "app/grade/error_bound_region.h"
#include "grader/oracle/wide_vec.h"
#include "stages/6_shading/shading.h"

namespace raystep {

// What the error-bound rule of spawn_ray (stages/6_shading/shading.h) promises about the origin
// of a ray that leaves a surface, decided in long double. Stage 6 judges spawn_ray and
// shadow_ray by it, stage 7 the mirror ray, which leaves by the same rule.

/// The geometric normal of `point` on the side a ray along `direction` leaves to; in the tangent
/// plane (or for a NaN direction), the normal as given.
WideVec leaving_normal(const SurfacePoint& point, const Vec3& direction);

/// The region an error-bound origin may be in (app/grade/error_bound_region.h), with n the
/// leaving normal and d = sum |n_i| error_i. `ulps` is 4 ulps of the point's largest coordinate
/// (or of d, if larger; or 4 subnormal steps, at the origin with no error): rounding and the
/// one-ulp step move the origin by that much, along n and sideways, and the step's direction is
/// not judged.
using grade::ErrorBoundOrigin;

/// The region for a ray leaving `point` along `direction`.
ErrorBoundOrigin error_bound_origin(const SurfacePoint& point, const Vec3& direction);

}  // namespace raystep
