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
    // I = local + (Ks + Kt F) I(reflected) + Kt (1 - F) I(refracted), as the header says.
    RAYSTEP_TODO(9, "radiance_with_refraction", "Radiance through glass");
}

}  // namespace raystep
