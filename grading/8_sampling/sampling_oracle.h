#pragma once

#include "base/scene/scene.h"
#include "stages/2_rays/camera.h"
#include "stages/6_shading/shading.h"

namespace raystep {

// Exact or long-double expectations for stage 8's checks (stage8_*.cpp):
// the rays through film points, a quad light's samples, the integrals the random estimators
// must average to, and the share of a pixel an edge covers. Written from the handout's formulas,
// not from the reference solution, so that a mistake in one does not hide in the other.

/// The ray through film point `film` (pixel coordinates) of a perspective camera, computed in
/// long double and rounded once: eye, normalize(alpha hw u + beta hh v - w) with
/// alpha = 2 x / width - 1, beta = 1 - 2 y / height.
Ray expected_perspective_ray(const PerspectiveCamera& camera, const Vec2& film);

/// The orthographic ray through `film`: eye + x u + y v with x, y across the window, along -w.
Ray expected_orthographic_ray(const OrthographicCamera& camera, const Vec2& film);

/// sample_quad_light's answer in long double, rounded once: the direction and distance to
/// y = a + u.x ab + u.y ac and radiance max((ab x ac) . L, 0) / (pi d^2 count).
LightSample expected_quad_light_sample(const QuadLight& light, const Vec3& point, const Vec2& u,
                                       int count);

/// What one light sample at `u` adds, as the mean's integrand: blinn_phong of
/// expected_quad_light_sample(light, point, u, 1), in long double; 0 behind the surface.
Color quad_light_term(const Material& material, const SurfacePoint& point, const QuadLight& light,
                      const Vec2& u);

/// The exact mean of quad_light_shading over its random samples: the integral of
/// quad_light_term over u in [0, 1)^2 with u.x below `blocked_below` unseen (0: nothing blocked).
/// The midpoint rule on `resolution` x `resolution` cells placed so that u.x = blocked_below is a
/// cell boundary, and again on cells half as wide, combined by Richardson extrapolation: the
/// integrand is smooth where it is not 0, so the rule's error is c h^2 + O(h^4), and
/// (4 I(h/2) - I(h)) / 3 cancels the first term. Resolution 128 puts the error near 1e-9 of the
/// value or below for the checks' lights, where the plain rule needs 1024 x 1024 cells, twelve
/// times the evaluations, for 1e-7 to 6e-7 (the figures: docs/measurements/grading-time.md).
Color quad_light_integral(const Material& material, const SurfacePoint& point,
                          const QuadLight& light, double blocked_below, int resolution);

/// quad_light_shading's answer for the regular pattern: the mean of quad_light_term over the
/// n x n stratum centres that are not blocked.
Color regular_quad_light_sum(const Material& material, const SurfacePoint& point,
                             const QuadLight& light, int strata_per_side, double blocked_below);

/// The share of the rectangle [low, high] where (p - through) . normal >= 0: its area clipped
/// by the half-plane, over its own, exactly but for rounding.
double half_plane_share(const Vec2& low, const Vec2& high, const Vec2& through, const Vec2& normal);

}  // namespace raystep
