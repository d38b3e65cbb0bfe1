#pragma once

#include <vector>

#include "base/scene/scene.h"
#include "stages/6_shading/shading.h"

namespace raystep {

// The local model of each dialect (scene.h, SceneDialect). CSE167's is stage 6's Blinn-Phong. The
// CSE168 course's is its Phong BRDF,
//
//   f(L, V) = Kd / pi + Ks (s + 2) / (2 pi) max(R . L, 0)^s,   R = 2 (N . V) N - V,
//
// a lobe about the mirror direction of the eye, whose (s + 2) / (2 pi) keeps the light it
// reflects at most Ks: narrower and brighter than Blinn-Phong's max(N . H, 0)^s at the same s.
// A light sample's term is f times pi, the light's intensity and max(N . L, 0): the pi because
// raystep's light intensities are CSE167's, and a quad light's samples carry the 1/pi that
// makes Kd the albedo (stage 8's sample_quad_light), so that both dialects light a diffuse
// surface alike.

/// One light's term in the CSE168 dialect, its visibility left out:
/// intensity max(N . L, 0) (Kd + Ks (s + 2) / 2 max(R . L, 0)^s), with N the shading normal.
Color phong_lobe_term(const Material& material, const SurfacePoint& point,
                      const LightSample& light);

/// One light's term in the dialect: stage 6's blinn_phong, or phong_lobe_term.
Color light_term(SceneDialect dialect, const Material& material, const SurfacePoint& point,
                 const LightSample& light);

/// A + E + the light terms of the lights that reach the point: stage 6's local_shading in the
/// CSE167 dialect.
Color local_colour(SceneDialect dialect, const Material& material, const SurfacePoint& point,
                   const std::vector<LightSample>& visible_lights);

}  // namespace raystep
