// Stage 11: normal mapping and bump mapping. Handout: docs/stage11.md.

#include "base/errors/not_implemented.h"
#include "stages/11_surface_detail/surface_detail.h"

namespace raystep {

Vec3 normal_from_map(const TangentFrame& frame, const Color& texel) {
    // (2r - 1) t + (2g - 1) b + (2b - 1) n, normalized.
    RAYSTEP_TODO(11, "normal_from_map", "Normal mapping");
}

Vec2 height_slopes(const Image& height_map, const Vec2& uv, WrapMode wrap, double scale) {
    // Central differences one texel apart, each height a bilinear lookup's red channel.
    RAYSTEP_TODO(11, "height_slopes", "Bump mapping");
}

Vec3 bump_normal(const SurfaceDerivatives& derivatives, const Vec3& normal, const Vec2& slopes) {
    // (dp/du + h_u n) x (dp/dv + h_v n), normalized and turned to n's side.
    RAYSTEP_TODO(11, "bump_normal", "Bump mapping");
}

}  // namespace raystep
