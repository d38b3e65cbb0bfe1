#pragma once

#include "base/scene/scene.h"
#include "stages/6_shading/shading.h"

namespace raystep {

/// A spot light seen from `point`: stage 6's point light (sample_light, with the spot's
/// attenuation) whose colour is scaled by the spot's falloff, cos(angle)^exponent, angle between
/// the spot's axis and the direction from the light to the point, and 0 beyond `cutoff_degrees`
/// of the axis (a hard edge, as OpenGL's fixed-function spot light has). Outside the cone the
/// intensity is exactly black, so the renderer sends no shadow ray. Throws std::domain_error
/// when the point is at the light, as sample_light does.
LightSample sample_spot_light(const SpotLight& light, const Vec3& point);

/// The falloff alone: cos(angle)^exponent inside the cone, 0 outside it and at the light.
double spot_falloff(const SpotLight& light, const Vec3& point);

}  // namespace raystep
