// Stage 10: directions over the hemisphere and their densities. Handout: docs/stage10.md.

#include "base/errors/not_implemented.h"
#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

Frame frame_around(const Vec3& n) {
    // Stage 1's orthonormal_frame(n, b), b the axis (1,0,0), (0,1,0) or (0,0,1) along which n's
    // component is smallest in size: a fixed b would be parallel to some normal.
    RAYSTEP_TODO(10, "frame_around", "A frame around the normal");
}

Vec3 to_world(const Frame& frame, const Vec3& local) {
    // x u + y v + z w.
    RAYSTEP_TODO(10, "to_world", "A frame around the normal");
}

Vec3 to_local(const Frame& frame, const Vec3& world) {
    // (d . u, d . v, d . w): the inverse of to_world, since the frame is orthonormal.
    RAYSTEP_TODO(10, "to_local", "A frame around the normal");
}

Vec3 uniform_hemisphere(const Vec2& u) {
    // cos(theta) = u.x, sin(theta) = sqrt(1 - cos^2), phi = 2 pi u.y:
    // (sin cos(phi), sin sin(phi), cos).
    RAYSTEP_TODO(10, "uniform_hemisphere", "Sampling the hemisphere");
}

double uniform_hemisphere_pdf(const Vec3& direction) {
    // 1 / (2 pi), the hemisphere's solid angle inverted; 0 below it.
    RAYSTEP_TODO(10, "uniform_hemisphere_pdf", "Sampling the hemisphere");
}

Vec3 cosine_hemisphere(const Vec2& u) {
    // r = sqrt(u.x), phi = 2 pi u.y on the unit disk, then z = sqrt(1 - r^2).
    RAYSTEP_TODO(10, "cosine_hemisphere", "Sampling the hemisphere");
}

double cosine_hemisphere_pdf(const Vec3& direction) {
    // cos(theta) / pi, 0 below the hemisphere.
    RAYSTEP_TODO(10, "cosine_hemisphere_pdf", "Sampling the hemisphere");
}

Vec3 phong_lobe(const Vec2& u, double exponent) {
    // cos(alpha) = u.x^(1 / (s + 1)), phi = 2 pi u.y.
    RAYSTEP_TODO(10, "phong_lobe", "Sampling a lobe");
}

double phong_lobe_pdf(const Vec3& direction, double exponent) {
    // (s + 1) / (2 pi) cos^s(alpha), 0 below the lobe's equator.
    RAYSTEP_TODO(10, "phong_lobe_pdf", "Sampling a lobe");
}

double ggx_distribution(const Vec3& half_vector, double roughness) {
    // alpha^2 / (pi cos^4 (alpha^2 + tan^2)^2), 0 for h.z <= 0: the denominator as
    // (alpha^2 cos^2 + sin^2)^2, sin^2 = x^2 + y^2.
    RAYSTEP_TODO(10, "ggx_distribution", "Sampling a lobe");
}

Vec3 ggx_half_vector(const Vec2& u, double roughness) {
    // theta = atan(alpha sqrt(u.x) / sqrt(1 - u.x)), phi = 2 pi u.y.
    RAYSTEP_TODO(10, "ggx_half_vector", "Sampling a lobe");
}

double ggx_half_vector_pdf(const Vec3& half_vector, double roughness) {
    // D(h) cos(theta_h).
    RAYSTEP_TODO(10, "ggx_half_vector_pdf", "Sampling a lobe");
}

}  // namespace raystep
