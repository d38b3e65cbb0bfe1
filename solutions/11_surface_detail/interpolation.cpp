// Stage 11 reference solution: values interpolated over a triangle, and a sphere's texture
// coordinates.

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "stages/11_surface_detail/surface_detail.h"

namespace raystep {

Vec3 interpolate_normal(const Vec3& n0, const Vec3& n1, const Vec3& n2, double beta, double gamma) {
    const double alpha = 1.0 - beta - gamma;
    const Vec3 sum = alpha * n0 + beta * n1 + gamma * n2;
    const double length = glm::length(sum);
    // Written to reject NaN too: a NaN sum is no normal either.
    if (!(length > 0.0))
        throw std::domain_error("interpolate_normal: the vertex normals sum to zero here");
    return sum / length;
}

Vec2 interpolate_uv(const Vec2& uv0, const Vec2& uv1, const Vec2& uv2, double beta, double gamma) {
    return (1.0 - beta - gamma) * uv0 + beta * uv1 + gamma * uv2;
}

Vec2 sphere_uv(const Vec3& normal) {
    constexpr double kPi = glm::pi<double>();
    const double theta = std::atan2(std::sqrt(normal.x * normal.x + normal.z * normal.z), normal.y);
    const double phi = kPi + std::atan2(normal.x, normal.z);
    return {phi / (2.0 * kPi), 1.0 - theta / kPi};
}

}  // namespace raystep
