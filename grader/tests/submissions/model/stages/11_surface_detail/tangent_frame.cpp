// Stage 11: the surface's derivatives and the tangent frame. Handout: docs/stage11.md.

#include "stages/11_surface_detail/surface_detail.h"
#include "stages/1_vectors/vectors.h"

namespace raystep {

std::optional<SurfaceDerivatives> surface_derivatives(const Vec3& p0, const Vec3& p1,
                                                      const Vec3& p2, const Vec2& uv0,
                                                      const Vec2& uv1, const Vec2& uv2) {
    const double du1 = uv1.x - uv0.x, dv1 = uv1.y - uv0.y;
    const double du2 = uv2.x - uv0.x, dv2 = uv2.y - uv0.y;
    const double det = du1 * dv2 - du2 * dv1;
    if (det == 0.0) return std::nullopt;
    const Vec3 e1 = p1 - p0;
    const Vec3 e2 = p2 - p0;
    SurfaceDerivatives d;
    d.dpdu = (e1 * dv2 - e2 * dv1) / det;
    d.dpdv = (e2 * du1 - e1 * du2) / det;
    return d;
}

std::optional<TangentFrame> tangent_frame(const SurfaceDerivatives& derivatives,
                                          const Vec3& normal) {
    const Vec3 t = derivatives.dpdu - project_onto(derivatives.dpdu, normal);
    const double size = length(t);
    if (!(size > 0.0)) return std::nullopt;
    TangentFrame frame;
    frame.normal = normal;
    frame.tangent = t / size;
    frame.bitangent = cross(normal, frame.tangent);
    if (dot(frame.bitangent, derivatives.dpdv) < 0.0) frame.bitangent = -frame.bitangent;
    return frame;
}

}  // namespace raystep
