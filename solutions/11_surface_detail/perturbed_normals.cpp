// Stage 11 reference solution: normal mapping and bump mapping.

#include <stdexcept>

#include <glm/geometric.hpp>

#include "stages/11_surface_detail/surface_detail.h"

namespace raystep {

Vec3 normal_from_map(const TangentFrame& frame, const Color& texel) {
    const Vec3 local = 2.0 * texel - 1.0;
    const Vec3 world = local.x * frame.tangent + local.y * frame.bitangent + local.z * frame.normal;
    const double length = glm::length(world);
    if (!(length > 0.0))
        throw std::domain_error("normal_from_map: the texel (0.5, 0.5, 0.5) holds no direction");
    return world / length;
}

Vec2 height_slopes(const Image& height_map, const Vec2& uv, WrapMode wrap, double scale) {
    const double du = 1.0 / height_map.width();
    const double dv = 1.0 / height_map.height();
    const auto height = [&](double u, double v) {
        return scale * texture_bilinear(height_map, {u, v}, wrap).r;
    };
    return {(height(uv.x + du, uv.y) - height(uv.x - du, uv.y)) / (2.0 * du),
            (height(uv.x, uv.y + dv) - height(uv.x, uv.y - dv)) / (2.0 * dv)};
}

Vec3 bump_normal(const SurfaceDerivatives& derivatives, const Vec3& normal, const Vec2& slopes) {
    const Vec3 bumped =
        glm::cross(derivatives.dpdu + slopes.x * normal, derivatives.dpdv + slopes.y * normal);
    const double length = glm::length(bumped);
    if (!(length > 0.0))
        throw std::domain_error("bump_normal: the bumped surface's derivatives are parallel");
    return (glm::dot(bumped, normal) < 0.0 ? -bumped : bumped) / length;
}

}  // namespace raystep
