#pragma once

#include "base/math/types.h"
#include "base/scene/scene.h"

namespace raystep {

// The CSE168 course's `integrator analyticdirect`: a quad light's irradiance at a point, by
// Lambert's formula (1760) for a polygon of uniform radiance L, with no sampling and no shadows:
//
//   E = L Phi . N,   Phi = 1/2 sum over the polygon's edges k of theta_k Gamma_k,
//
// theta_k the angle the edge (v_k, v_k+1) subtends at the point, Gamma_k the unit normal of the
// plane through the point and the edge. The formula integrates cos(theta) over the polygon's solid
// angle, which is right only where the whole polygon lies above the surface's horizon, so the
// polygon is first clipped to the half-space N . (x - p) >= 0. A diffuse surface then reflects
// Kd / pi E.

/// E / L: the cosine-weighted solid angle of the quad light seen from `point` on a surface of
/// unit normal `normal`; 0 where the point is behind the light's emitting side (ac x ab) or the
/// light below the horizon. Between 0 and pi.
double quad_light_irradiance(const QuadLight& light, const Vec3& point, const Vec3& normal);

}  // namespace raystep
