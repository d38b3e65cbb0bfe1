#pragma once

#include <vector>

#include "base/scene/scene.h"
#include "stages/2_rays/ray.h"

namespace raystep {

// Stage 6: shading and shadows. Handout: docs/stage6.md.
//
// The CSE167 local model: at a point seen along a ray,
//
//   I = A + E + sum over lights i of  V_i L_i / att_i (Kd max(N . L_i, 0) + Ks max(N . H_i, 0)^s)
//
// with A, E, Kd, Ks, s the material's ambient, emission, diffuse, specular and shininess, L_i
// the unit direction to light i, H_i = normalize(L_i + V) the half vector towards the eye V,
// att_i the light's attenuation and V_i its visibility: 1 when a shadow ray reaches the light,
// 0 when something blocks it.

/// A point where a ray landed, as the renderer hands it to shading.
struct SurfacePoint {
    Vec3 position;        ///< the hit point
    Vec3 error;           ///< per coordinate, a bound on how far rounding put `position` off
                          ///< the surface, wide enough for intersection tests near it
                          ///< (renderer/surface_point.h)
    Vec3 normal;          ///< unit geometric normal, turned to the side the ray came from
    Vec3 shading_normal;  ///< unit normal for lighting (interpolated on `trinormal` triangles),
                          ///< on the same side as `normal`
    Vec3 to_eye;          ///< V: unit, from the point back towards the ray's origin
};

/// One light as seen from one point.
struct LightSample {
    Vec3 direction;   ///< L: unit, from the point towards the light
    double distance;  ///< to a point light; infinity for a directional light
    Color intensity;  ///< the light's colour divided by its attenuation at that distance
};

/// att = constant + linear d + quadratic d^2, the divisor of a point light's colour at
/// distance d.
double attenuation(const Attenuation& attenuation, double distance);

/// A point light seen from `point`. Throws std::domain_error when the point is at the light:
/// it has no direction to it.
LightSample sample_light(const PointLight& light, const Vec3& point);

/// A directional light: the same from everywhere, never attenuated.
LightSample sample_light(const DirectionalLight& light);

/// One light's term, V_i left out: intensity (Kd max(N . L, 0) + Ks max(N . H, 0)^s), with N
/// the shading normal. A light behind the surface (N . L <= 0) adds nothing, its highlight
/// neither. Where the eye is exactly opposite the light (L + V = 0, seen only through a bent
/// shading normal) no direction lies halfway: N . H counts as 0 there, never a throw or a NaN.
Color blinn_phong(const Material& material, const SurfacePoint& point, const LightSample& light);

/// I = A + E + the blinn_phong terms of the lights that reach the point.
Color local_shading(const Material& material, const SurfacePoint& point,
                    const std::vector<LightSample>& visible_lights);

// Rays that leave a surface (shadow rays here, mirror rays in stage 7) start by one of the
// rules of RayOffset (base/scene/scene.h): the scene's `rayoffset` command or `raystep render
// --ray-offset` picks one.

/// A ray leaving the surface at `point` along the unit `direction`, for hits up to `distance`
/// from the point, started as the rule says:
/// - along_ray: origin at the point, t over [epsilon, distance];
/// - along_normal: origin epsilon along the geometric normal, on the side `direction` leaves
///   to, t over [0, distance];
/// - error_bound: the same, but the offset is the point's rounding error along the normal,
///   sum |n_i| error_i, and each coordinate of the origin is then moved one more ulp away from
///   the point (pbrt-v4, OffsetRayOrigin), so that the origin is off the surface whatever its
///   scale, with no epsilon to tune.
Ray spawn_ray(const SurfacePoint& point, const Vec3& direction, double distance,
              const RayOffset& offset);

/// The shadow ray towards a light: spawn_ray in the light's direction, over its distance.
Ray shadow_ray(const SurfacePoint& point, const LightSample& light, const RayOffset& offset);

}  // namespace raystep
