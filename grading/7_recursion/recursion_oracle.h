#pragma once

// Stage 7's expectations in long double: the mirror ray at a surface point, and over a scripted
// scene (shade answers the script's hits in turn, then misses) every ray radiance should ask
// about, in order, and the colour it should add up. No CGAL: reflections and sums of products.

#include <optional>
#include <vector>

#include "app/grade/expected_ray.h"
#include "base/scene/ray_offset.h"
#include "grader/oracle/error_bound_origin.h"
#include "grader/oracle/wide_vec.h"
#include "stages/2_rays/ray.h"
#include "stages/6_shading/shading.h"
#include "stages/7_recursion/recursion.h"

namespace raystep {

/// A ray as stage 7's judges expect it (app/grade/expected_ray.h).
using grade::ExpectedRay;

/// A ray leaving `p` along the long-double unit direction `d`, unbounded, by the offset's rule
/// (stage 6's spawn_ray): from the point itself, epsilon along the leaving side's normal, or from
/// the error-bound region; its direction within `direction_tolerance`. Stage 7's mirror ray and
/// stage 9's refracted ray both leave so.
ExpectedRay expected_leaving_ray(const SurfacePoint& p, const WideVec& d, Wide direction_tolerance,
                                 const RayOffset& offset);

/// The mirror ray at `p`: -V reflected about the shading normal, normalized, leaving by the
/// offset's rule (stage 6's spawn_ray) with no upper bound: from the point itself, epsilon along
/// the leaving side's normal, or from the error-bound region. The leaving side is that of the
/// direction in long double; cases keep the mirror ray well off the geometric tangent plane,
/// where no rounding can change it.
ExpectedRay expected_reflection(const SurfacePoint& p, const RayOffset& offset);

/// What shade returns on each call in turn: a shaded hit, or nullopt for a miss (and past the
/// end, misses).
using Script = std::vector<std::optional<ShadedHit>>;

/// The colour and the rays that radiance should ask shade about, in order: the eye ray, then one
/// mirror ray per hit while bounces remain and the reflectance is not black. Each term of the
/// colour is the local colour times a product of reflectances, all non-negative: a few roundings
/// per product and one per sum, relative to the terms' sum.
struct ExpectedRadiance {
    WideVec colour{0};
    WideVec colour_tolerance{0};
    std::vector<ExpectedRay> rays;
};

/// radiance(shade, eye, bounces, offset) over the script.
ExpectedRadiance expected_radiance(const Script& script, const Ray& eye, int bounces,
                                   const RayOffset& offset);

}  // namespace raystep
