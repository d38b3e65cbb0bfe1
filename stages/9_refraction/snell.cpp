// Stage 9: Snell's law and the Fresnel reflectance. Handout: docs/stage9.md.

#include "base/errors/not_implemented.h"
#include "stages/9_refraction/refraction.h"

namespace raystep {

std::optional<Vec3> refract(const Vec3& incident, const Vec3& normal, double eta) {
    // cos1 = -D . N;  sin^2(theta2) = eta^2 (1 - cos1^2); above 1: total internal reflection.
    // Otherwise cos2 = sqrt(1 - sin^2(theta2)) and T = eta D + (eta cos1 - cos2) N.
    RAYSTEP_TODO(9, "refract", "Snell's law");
}

double fresnel_exact(double cos_incident, double n1, double n2) {
    // r_s = (n1 cos1 - n2 cos2) / (n1 cos1 + n2 cos2), r_p = (n2 cos1 - n1 cos2) / (n2 cos1 +
    // n1 cos2), F = (r_s^2 + r_p^2) / 2; 1 under total internal reflection.
    RAYSTEP_TODO(9, "fresnel_exact", "Fresnel");
}

double fresnel_schlick(double cos_incident, double n1, double n2) {
    // R0 = ((n1 - n2) / (n1 + n2))^2, F = R0 + (1 - R0)(1 - cos)^5 with cos on the less dense
    // side.
    RAYSTEP_TODO(9, "fresnel_schlick", "Fresnel");
}

}  // namespace raystep
