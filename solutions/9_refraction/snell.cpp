// Stage 9 reference solution: Snell's law and the Fresnel reflectance.

#include <algorithm>
#include <cmath>

#include "stages/1_vectors/vectors.h"
#include "stages/9_refraction/refraction.h"

namespace raystep {

std::optional<Vec3> refract(const Vec3& incident, const Vec3& normal, double eta) {
    const double cos1 = -dot(incident, normal);
    const double sin2_squared = eta * eta * std::max(0.0, 1.0 - cos1 * cos1);
    if (sin2_squared > 1.0) return std::nullopt;
    const double cos2 = std::sqrt(1.0 - sin2_squared);
    // T = eta D + (eta cos1 - cos2) N: the tangential part of D scaled by eta, the normal part
    // whatever makes T unit. Normalized again because rounding moves its length off 1.
    return normalize(eta * incident + (eta * cos1 - cos2) * normal);
}

double fresnel_exact(double cos_incident, double n1, double n2) {
    const double cos1 = std::clamp(cos_incident, 0.0, 1.0);
    const double sin2 = n1 / n2 * std::sqrt(std::max(0.0, 1.0 - cos1 * cos1));
    if (sin2 >= 1.0) return 1.0;
    const double cos2 = std::sqrt(std::max(0.0, 1.0 - sin2 * sin2));
    const double r_s = (n1 * cos1 - n2 * cos2) / (n1 * cos1 + n2 * cos2);
    const double r_p = (n2 * cos1 - n1 * cos2) / (n2 * cos1 + n1 * cos2);
    return 0.5 * (r_s * r_s + r_p * r_p);
}

double fresnel_schlick(double cos_incident, double n1, double n2) {
    double cos = std::clamp(cos_incident, 0.0, 1.0);
    if (n1 > n2) {
        // Leaving the denser medium: Schlick's cosine is the one on the less dense side.
        const double sin2 = n1 / n2 * std::sqrt(std::max(0.0, 1.0 - cos * cos));
        if (sin2 >= 1.0) return 1.0;
        cos = std::sqrt(std::max(0.0, 1.0 - sin2 * sin2));
    }
    const double r0 = (n1 - n2) / (n1 + n2);
    return r0 * r0 + (1.0 - r0 * r0) * std::pow(1.0 - cos, 5.0);
}

}  // namespace raystep
