#pragma once

#include <optional>

#include "base/math/random_stream.h"
#include "renderer/pixel_observer.h"
#include "renderer/render_scene.h"
#include "stages/7_recursion/recursion.h"

namespace raystep {

/// What a ray that leaves the scene sees, as a shaded hit for stage 7's and stage 9's recursion:
/// the scene's background as its local colour, reflecting and transmitting nothing, so that no
/// ray follows it. nullopt when the background is black: then the miss stays a miss, and stage
/// 7's "black when it misses" gives the same image as a scene without a background.
///
/// This keeps both stages' contracts as they are (a miss is black) and puts the background in
/// the renderer, the one place that knows the scene: the shade function the renderer hands to
/// radiance turns a miss into this hit. Eye rays, mirror rays and refracted rays all see it.
std::optional<ShadedHit> background_hit(const Ray& ray, const Color& background);

/// The full view's colour along an eye ray whose closest hit is `eye_hit` (already found), for
/// a scene with bounces to follow (RenderScene::bounces > 0): stage 7's radiance over stage 6's
/// colours; where the scene uses refraction, stage 9's radiance_with_refraction instead, the eye
/// ray starting in air (an empty MediumStack: a camera inside glass is not modelled), with
/// scene_solids' numbering, the scene's Fresnel choice and maxdepth bounces. Misses see the
/// background. Quad lights draw their samples from `light_random` (nullptr when the scene has
/// none). Every later ray and its shading is told to `observer`, then the colour.
Color full_colour(const RenderScene& render_scene, const Ray& eye_ray,
                  const std::optional<PrimitiveHit>& eye_hit, RandomStream* light_random,
                  PixelObserver& observer);

}  // namespace raystep
