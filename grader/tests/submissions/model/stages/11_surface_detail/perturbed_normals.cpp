// Stage 11: normal mapping and bump mapping. Handout: docs/stage11.md.

#include <stdexcept>

#include "stages/11_surface_detail/surface_detail.h"
#include "stages/1_vectors/vectors.h"

namespace raystep {

Vec3 normal_from_map(const TangentFrame& frame, const Color& texel) {
    const Vec3 n = (2.0 * texel.r - 1.0) * frame.tangent + (2.0 * texel.g - 1.0) * frame.bitangent +
                   (2.0 * texel.b - 1.0) * frame.normal;
    const double size = length(n);
    if (!(size > 0.0)) throw std::domain_error("normal_from_map: a texel with no direction");
    return n / size;
}

Vec2 height_slopes(const Image& height_map, const Vec2& uv, WrapMode wrap, double scale) {
    const double du = 1.0 / height_map.width();
    const double dv = 1.0 / height_map.height();
    const double right = texture_bilinear(height_map, {uv.x + du, uv.y}, wrap).r;
    const double left = texture_bilinear(height_map, {uv.x - du, uv.y}, wrap).r;
    const double up = texture_bilinear(height_map, {uv.x, uv.y + dv}, wrap).r;
    const double down = texture_bilinear(height_map, {uv.x, uv.y - dv}, wrap).r;
    return {scale * (right - left) / (2.0 * du), scale * (up - down) / (2.0 * dv)};
}

Vec3 bump_normal(const SurfaceDerivatives& derivatives, const Vec3& normal, const Vec2& slopes) {
    const Vec3 n =
        cross(derivatives.dpdu + slopes.x * normal, derivatives.dpdv + slopes.y * normal);
    const double size = length(n);
    if (!(size > 0.0)) throw std::domain_error("bump_normal: no bumped normal");
    return dot(n, normal) < 0.0 ? -n / size : n / size;
}

}  // namespace raystep
