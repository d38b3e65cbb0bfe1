// Stage 7: recursive reflection. Handout: docs/stage7.md. Use your stage-1 reflect and normalize
// and your stage-6 spawn_ray here.

#include "stages/7_recursion/recursion.h"

#include <limits>

#include "base/errors/not_implemented.h"
#include "stages/1_vectors/vectors.h"

namespace raystep {

Ray reflected_ray(const SurfacePoint& point, const RayOffset& offset) {
    // The ray came in along -V; the mirror sends it on along R = reflect(-V, N), N the shading
    // normal (normalize R: rounding moves its length off 1). It leaves the surface like a
    // shadow ray, by spawn_ray with the same offset, but nothing bounds it: distance infinity.
    RAYSTEP_TODO(7, "reflected_ray", "The reflected ray");
}

Color radiance(const ShadeFunction& shade, const Ray& ray, int bounces_left,
               const RayOffset& offset) {
    // hit = shade(ray); a miss is black. Otherwise
    //   I = local + Ks radiance(reflected ray, bounces_left - 1)   while bounces_left > 0,
    // and just local when no bounce is left or Ks is black, exactly (0, 0, 0): then do not
    // trace the reflected ray at all, it would cost a whole ray and add nothing. A weak mirror
    // is not black: it still reflects.
    RAYSTEP_TODO(7, "radiance", "Recursive reflection");
}

}  // namespace raystep
