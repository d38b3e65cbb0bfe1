// Stage 11 reference solution: the surface's derivatives and the tangent frame.

#include <glm/geometric.hpp>

#include "stages/11_surface_detail/surface_detail.h"

namespace raystep {

std::optional<SurfaceDerivatives> surface_derivatives(const Vec3& p0, const Vec3& p1,
                                                      const Vec3& p2, const Vec2& uv0,
                                                      const Vec2& uv1, const Vec2& uv2) {
    const Vec3 e1 = p1 - p0;
    const Vec3 e2 = p2 - p0;
    const Vec2 d1 = uv1 - uv0;
    const Vec2 d2 = uv2 - uv0;
    const double det = d1.x * d2.y - d2.x * d1.y;
    if (det == 0.0) return std::nullopt;
    // [e1 e2] = [dp/du dp/dv] [[du1 du2] [dv1 dv2]], times the 2x2 inverse.
    return SurfaceDerivatives{(d2.y * e1 - d1.y * e2) / det, (d1.x * e2 - d2.x * e1) / det};
}

std::optional<TangentFrame> tangent_frame(const SurfaceDerivatives& derivatives,
                                          const Vec3& normal) {
    const Vec3 across = derivatives.dpdu - glm::dot(normal, derivatives.dpdu) * normal;
    const double length = glm::length(across);
    if (!(length > 0.0)) return std::nullopt;
    const Vec3 tangent = across / length;
    Vec3 bitangent = glm::cross(normal, tangent);
    if (glm::dot(bitangent, derivatives.dpdv) < 0.0) bitangent = -bitangent;
    return TangentFrame{tangent, bitangent, normal};
}

}  // namespace raystep
