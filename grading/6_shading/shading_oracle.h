#pragma once

// Stage 6's expectations in long double: attenuation, light samples, one light's Blinn-Phong term
// and the local model's sum, each with how far a right implementation in double may land from
// it. No CGAL: these are sums, products and one power, 11 bits beyond a double.

#include <vector>

#include "base/scene/scene.h"
#include "grader/oracle/wide_vec.h"
#include "stages/6_shading/shading.h"

namespace raystep {

/// k_c + k_l d + k_q d^2. Every term is non-negative, so a right implementation lands within a
/// few roundings of the sum.
Wide wide_attenuation(const Attenuation& a, Wide distance);

/// A light sample as the judge expects it: the unit direction to the light, its distance
/// (infinite for a directional light) and intensity, and how far the intensity may be off.
struct WideLightSample {
    WideVec direction;
    Wide distance = 0;
    WideVec intensity;
    WideVec intensity_tolerance;
};

/// A point light seen from `point`: the colour over the attenuation at its distance. The
/// distance is a few ulps off, its square twice that; the division rounds once more.
WideLightSample wide_point_light(const PointLight& light, const Vec3& point);

/// A directional light: never attenuated, the colour itself, exactly, at infinity.
WideLightSample wide_directional_light(const DirectionalLight& light);

/// A colour and how far a right implementation may round it, per channel.
struct WideColor {
    WideVec value;
    WideVec tolerance;
};

/// One light's Blinn-Phong term, I (Kd max(N . L, 0) + Ks max(N . H, 0)^s), black when the
/// light is behind the shading normal; where L + V = 0 there is no half vector and N . H counts
/// as 0. The cosines round by a few ulps, which (N . H)^s multiplies by s / (N . H); each product
/// and sum once more.
WideColor wide_blinn_phong(const Material& m, const SurfacePoint& p, const LightSample& l);

/// The local model: ambient, emission and each light's term; the sum rounds once per term, in
/// whatever order.
WideColor wide_local_shading(const Material& m, const SurfacePoint& p,
                             const std::vector<LightSample>& lights);

}  // namespace raystep
