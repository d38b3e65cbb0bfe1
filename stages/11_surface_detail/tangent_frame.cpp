// Stage 11: the surface's derivatives and the tangent frame. Handout: docs/stage11.md.

#include "base/errors/not_implemented.h"
#include "stages/11_surface_detail/surface_detail.h"

namespace raystep {

std::optional<SurfaceDerivatives> surface_derivatives(const Vec3& p0, const Vec3& p1,
                                                      const Vec3& p2, const Vec2& uv0,
                                                      const Vec2& uv1, const Vec2& uv2) {
    // e1 = du1 dp/du + dv1 dp/dv and e2 = du2 dp/du + dv2 dp/dv: two equations in two unknown
    // vectors. Cramer's rule, with det = du1 dv2 - du2 dv1.
    RAYSTEP_TODO(11, "surface_derivatives", "The tangent frame");
}

std::optional<TangentFrame> tangent_frame(const SurfaceDerivatives& derivatives,
                                          const Vec3& normal) {
    // Gram-Schmidt: take away dp/du's part along n, then normalize. The bitangent is n x t,
    // on dp/dv's side.
    RAYSTEP_TODO(11, "tangent_frame", "The tangent frame");
}

}  // namespace raystep
