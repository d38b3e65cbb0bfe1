// Stage 11: values interpolated over a triangle, and a sphere's texture coordinates. Handout:
// docs/stage11.md.

#include "base/errors/not_implemented.h"
#include "stages/11_surface_detail/surface_detail.h"

namespace raystep {

Vec3 interpolate_normal(const Vec3& n0, const Vec3& n1, const Vec3& n2, double beta, double gamma) {
    // alpha = 1 - beta - gamma weighs n0; normalize the weighted sum, which may be shorter than
    // 1 even for unit vertex normals.
    RAYSTEP_TODO(11, "interpolate_normal", "Smooth normals");
}

Vec2 interpolate_uv(const Vec2& uv0, const Vec2& uv1, const Vec2& uv2, double beta, double gamma) {
    // The same weights as the normal's, and nothing to normalize.
    RAYSTEP_TODO(11, "interpolate_uv", "Texture coordinates");
}

Vec2 sphere_uv(const Vec3& normal) {
    // theta = atan2(sqrt(x^2 + z^2), y), phi = pi + atan2(x, z); u = phi / (2 pi), v = 1 -
    // theta / pi.
    RAYSTEP_TODO(11, "sphere_uv", "A sphere's texture coordinates");
}

}  // namespace raystep
