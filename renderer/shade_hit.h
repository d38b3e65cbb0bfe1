#pragma once

#include "base/math/random_stream.h"
#include "renderer/pixel_observer.h"
#include "renderer/render_scene.h"
#include "stages/7_recursion/recursion.h"

namespace raystep {

/// Stage 6 at one hit: the surface point (surface_point), every point, directional and spot
/// light (spot_light.h) sampled and, when it is in front of the surface, tested with a shadow
/// ray; then the dialect's local model over the lights that reach the point (local_model.h).
/// Lights behind the surface get no shadow ray: the surface itself blocks them, and a spot light
/// sends none outside its cone. Then stage 8: each quad light's quad_light_shading, with the
/// scene's `lightsamples` samples drawn from `light_random` (which may be nullptr only when the
/// scene has no quad lights; sample_streams.h says which stream a render hands in); in the
/// CSE168 dialect the same samples shaded by its Phong lobe, or with `integrator analyticdirect`
/// each light's exact unshadowed irradiance (polygon_irradiance.h). Every step is told to
/// `observer`.
ShadedHit shade_hit(const RenderScene& render_scene, const Ray& ray, const PrimitiveHit& hit,
                    RandomStream* light_random, PixelObserver& observer);

}  // namespace raystep
