// Stage 11: values interpolated over a triangle, and a sphere's texture coordinates. Handout:
// docs/stage11.md.

#include <cmath>
#include <stdexcept>

#include "stages/11_surface_detail/surface_detail.h"
#include "stages/1_vectors/vectors.h"

namespace raystep {

Vec3 interpolate_normal(const Vec3& n0, const Vec3& n1, const Vec3& n2, double beta, double gamma) {
    const Vec3 sum = n0 + beta * (n1 - n0) + gamma * (n2 - n0);
    const double size = length(sum);
    if (!(size > 0.0)) throw std::domain_error("interpolate_normal: the normals cancel");
    return sum / size;
}

Vec2 interpolate_uv(const Vec2& uv0, const Vec2& uv1, const Vec2& uv2, double beta, double gamma) {
    const double alpha = 1.0 - beta - gamma;
    return {alpha * uv0.x + beta * uv1.x + gamma * uv2.x,
            alpha * uv0.y + beta * uv1.y + gamma * uv2.y};
}

Vec2 sphere_uv(const Vec3& normal) {
    const double pi = std::acos(-1.0);
    const double theta = std::atan2(std::hypot(normal.x, normal.z), normal.y);
    const double phi = std::atan2(normal.x, normal.z) + pi;
    return {phi / (2.0 * pi), 1.0 - theta / pi};
}

}  // namespace raystep
