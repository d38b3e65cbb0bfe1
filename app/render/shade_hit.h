#pragma once

#include "app/render/pixel_record.h"
#include "app/render/render_scene.h"
#include "app/render/trace_log.h"
#include "stages/7_recursion/recursion.h"

namespace raystep {

/// Stage 6 at one hit: the surface point (surface_point), every light sampled and, when it is in
/// front of the surface, tested with a shadow ray; then the local model over the lights that
/// reach the point. Lights behind the surface get no shadow ray: the surface itself blocks them.
/// With a trace, every light, shadow ray and shading term is added to it; with a record, each
/// light's reach and term and the local colour are put in it.
ShadedHit shade_hit(const RenderScene& render_scene, const Ray& ray, const PrimitiveHit& hit,
                    TraceLog* trace, PixelRecord* record);

}  // namespace raystep
