#pragma once

#include "base/math/random_stream.h"
#include "renderer/pixel_observer.h"
#include "renderer/render_scene.h"

namespace raystep {

// `integrator pathtracer` (the CSE168 course's path tracer): what a camera ray sees is one path
// of stage 10's path_radiance (docs/stage10.md) over the scene. Its surfaces are the scene's
// primitives, each with its material's BRDF (`brdf`, `diffuse`, `specular`, `shininess`,
// `roughness`) and emission, and its quad lights, seen as seen_quad_light.h sees them (radiance
// from the emitting side, black behind) and sampled by next event estimation; shadow rays are
// the scene's, which no quad light blocks. The scene's `maxdepth`, `russianroulette`,
// `importancesampling` and `nexteventestimation` are the path's settings (`maxdepth -1` ends by
// Russian roulette, and after kLongestPath bounces where it cannot: base/scene/scene.h). A path
// that leaves the
// scene sees black, as in the course: the `background` of a CSE167 scene is not an emitter.

/// One path's estimate of the radiance back along `ray`, drawing from `random`. Each ray the
/// path asks the scene for, and each shadow ray, is told to `observer`.
Color path_traced_colour(const RenderScene& render_scene, const Ray& ray, RandomStream& random,
                         PixelObserver& observer);

/// The indirect view's colour: the path's estimate less the same path cut after its direct light
/// (max_depth 1), drawn from a copy of `random`, so that the two share every step up to the cut
/// and their difference is what arrived by more than one bounce. Its expectation is the
/// difference of the two paths' whatever the order in which path_radiance draws its numbers;
/// sharing them leaves only the indirect light's own noise. Only the full path is told to
/// `observer`.
Color path_traced_indirect_colour(const RenderScene& render_scene, const Ray& ray,
                                  RandomStream& random, PixelObserver& observer);

}  // namespace raystep
