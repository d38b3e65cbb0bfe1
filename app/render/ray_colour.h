#pragma once

#include <optional>

#include "app/render/pixel_record.h"
#include "app/render/render_scene.h"
#include "app/render/trace_log.h"
#include "base/math/random_stream.h"
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
/// none). With a trace, every later ray and, at each surface that transmits, the media, Fresnel and
/// refracted ray are added to it; the record gets the eye ray's shading only, the steps a reference
/// trace compares.
Color full_colour(const RenderScene& render_scene, const Ray& eye_ray,
                  const std::optional<PrimitiveHit>& eye_hit, RandomStream* light_random,
                  TraceLog* trace, PixelRecord* record);

}  // namespace raystep
