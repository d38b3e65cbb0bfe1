// Stage 9: the refracted ray and radiance through glass. Handout: docs/stage9.md. Use your
// stage-6 spawn_ray and your stage-7 reflected_ray here.

#include "base/errors/not_implemented.h"
#include "stages/9_refraction/refraction.h"

namespace raystep {

std::optional<Ray> refracted_ray(const SurfacePoint& point, double n1, double n2,
                                 const RayOffset& offset) {
    // T = refract(-V, N, n1 / n2); nullopt under total internal reflection; else
    // spawn_ray(point, T, infinity, offset), which starts it on the far side.
    RAYSTEP_TODO(9, "refracted_ray", "The refracted ray");
}

Color radiance_with_refraction(const MediumShadeFunction& shade, const Ray& ray, int bounces_left,
                               const MediumStack& inside, bool schlick, const RayOffset& offset) {
    // hit = shade(ray): black on a miss, local alone when no bounce is left. Where Kt is not
    // black: beyond = after_crossing(inside, solid, entering), n1 and n2 the indices of inside
    // and beyond, F (Schlick's or exact) of cos1 = V . N, and the refracted ray; when there is
    // none (total internal reflection), F = 1. Then
    //   I = local + (Ks + Kt F) I(reflected ray, in inside) + Kt (1 - F) I(refracted, in beyond),
    // each with bounces_left - 1, and no ray traced where its weight is exactly black.
    RAYSTEP_TODO(9, "radiance_with_refraction", "Radiance through glass");
}

}  // namespace raystep
