// Stage 10 reference solution: directions over the hemisphere and their densities.

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

namespace {

constexpr double kTwoPi = 2.0 * glm::pi<double>();

// The direction at polar cosine `cos_theta` and azimuth 2 pi u about z. sin from 1 - cos^2,
// clamped: rounding may put cos a hair above 1.
Vec3 polar_direction(double cos_theta, double u) {
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    const double phi = kTwoPi * u;
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

}  // namespace

Frame frame_around(const Vec3& n) {
    // The axis of n's smallest component is at least acos(1/sqrt(3)) from n: never parallel.
    const Vec3 size = glm::abs(n);
    Vec3 axis(0.0);
    if (size.x <= size.y && size.x <= size.z) {
        axis.x = 1.0;
    } else if (size.y <= size.z) {
        axis.y = 1.0;
    } else {
        axis.z = 1.0;
    }
    return orthonormal_frame(n, axis);
}

Vec3 to_world(const Frame& frame, const Vec3& local) {
    return local.x * frame.u + local.y * frame.v + local.z * frame.w;
}

Vec3 to_local(const Frame& frame, const Vec3& world) {
    return {dot(world, frame.u), dot(world, frame.v), dot(world, frame.w)};
}

Vec3 uniform_hemisphere(const Vec2& u) {
    return polar_direction(u.x, u.y);
}

double uniform_hemisphere_pdf(const Vec3& direction) {
    return direction.z >= 0.0 ? 1.0 / kTwoPi : 0.0;
}

Vec3 cosine_hemisphere(const Vec2& u) {
    // A point uniform on the unit disk at radius sqrt(u.x), lifted: z^2 = 1 - r^2 = 1 - u.x.
    return polar_direction(std::sqrt(1.0 - u.x), u.y);
}

double cosine_hemisphere_pdf(const Vec3& direction) {
    return std::max(direction.z, 0.0) / glm::pi<double>();
}

Vec3 phong_lobe(const Vec2& u, double exponent) {
    return polar_direction(std::pow(u.x, 1.0 / (exponent + 1.0)), u.y);
}

double phong_lobe_pdf(const Vec3& direction, double exponent) {
    if (!(direction.z >= 0.0)) return 0.0;  // pow(0, 0) is 1: the test comes first
    return (exponent + 1.0) / kTwoPi * std::pow(direction.z, exponent);
}

double ggx_distribution(const Vec3& half_vector, double roughness) {
    const double cos_theta = half_vector.z;
    if (!(cos_theta > 0.0)) return 0.0;
    // cos^4 (alpha^2 + tan^2)^2 = (alpha^2 cos^2 + sin^2)^2, sin^2 = x^2 + y^2: no division by
    // cos^4, which overflows towards the horizon, and no 1 - cos^2, which cancels to 0 along the
    // normal when alpha^2 is below the rounding of 1 (D would be infinite there).
    const double alpha2 = roughness * roughness;
    const double sin2 = half_vector.x * half_vector.x + half_vector.y * half_vector.y;
    const double denominator = alpha2 * cos_theta * cos_theta + sin2;
    return alpha2 / (glm::pi<double>() * denominator * denominator);
}

Vec3 ggx_half_vector(const Vec2& u, double roughness) {
    // tan^2(theta) = alpha^2 u / (1 - u), so cos^2(theta) = (1 - u) / (1 + (alpha^2 - 1) u):
    // no tangent of an angle near pi/2.
    const double alpha2 = roughness * roughness;
    const double cos2 = (1.0 - u.x) / (1.0 + (alpha2 - 1.0) * u.x);
    return polar_direction(std::sqrt(cos2), u.y);
}

double ggx_half_vector_pdf(const Vec3& half_vector, double roughness) {
    return ggx_distribution(half_vector, roughness) * std::max(half_vector.z, 0.0);
}

}  // namespace raystep
