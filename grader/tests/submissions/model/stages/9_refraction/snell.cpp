// Stage 9: Snell's law and the Fresnel reflectance. Handout: docs/stage9.md.

#include <algorithm>
#include <cmath>

#include "stages/1_vectors/vectors.h"
#include "stages/9_refraction/refraction.h"

namespace raystep {

namespace {

// cos(theta2) from cos(theta1) and eta = n1 / n2, or a negative number under total internal
// reflection: sin^2(theta2) = eta^2 sin^2(theta1) by Snell's law.
double far_cosine_squared(double cos1, double eta) {
    return 1.0 - eta * eta * std::max(0.0, 1.0 - cos1 * cos1);
}

}  // namespace

std::optional<Vec3> refract(const Vec3& incident, const Vec3& normal, double eta) {
    const double cos1 = -dot(incident, normal);
    const double cos2_squared = far_cosine_squared(cos1, eta);
    if (cos2_squared < 0.0) return std::nullopt;
    const double cos2 = std::sqrt(cos2_squared);
    // The part of the direction along the surface shrinks by eta; the part along the normal is
    // -cos2 N, on the far side.
    return normalize(eta * (incident + cos1 * normal) - cos2 * normal);
}

double fresnel_exact(double cos_incident, double n1, double n2) {
    const double cos1 = std::clamp(cos_incident, 0.0, 1.0);
    const double cos2_squared = far_cosine_squared(cos1, n1 / n2);
    if (cos2_squared <= 0.0) return 1.0;
    const double cos2 = std::sqrt(cos2_squared);
    const double s = (n1 * cos1 - n2 * cos2) / (n1 * cos1 + n2 * cos2);
    const double p = (n1 * cos2 - n2 * cos1) / (n1 * cos2 + n2 * cos1);
    return (s * s + p * p) / 2.0;
}

double fresnel_schlick(double cos_incident, double n1, double n2) {
    double cos = std::clamp(cos_incident, 0.0, 1.0);
    if (n1 > n2) {
        // Out of the denser medium the angle that counts is the one outside, theta2.
        const double cos2_squared = far_cosine_squared(cos, n1 / n2);
        if (cos2_squared <= 0.0) return 1.0;
        cos = std::sqrt(cos2_squared);
    }
    const double r0 = (n1 - n2) / (n1 + n2);
    const double m = 1.0 - cos;
    return r0 * r0 + (1.0 - r0 * r0) * m * m * m * m * m;
}

}  // namespace raystep
