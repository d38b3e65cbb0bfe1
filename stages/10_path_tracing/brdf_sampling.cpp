// Stage 10: drawing directions shaped like the BRDF. Handout: docs/stage10.md.

#include "base/errors/not_implemented.h"
#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

double specular_probability(const SurfaceBrdf& brdf) {
    // t = mean(Ks) / (mean(Kd) + mean(Ks)); for GGX max(0.25, t).
    RAYSTEP_TODO(10, "specular_probability", "Importance sampling the BRDF");
}

Vec3 sample_brdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_eye, const Vec2& u,
                 double choice) {
    // choice < t: the specular lobe (Phong about r; GGX: wo reflected about a sampled h);
    // otherwise cosine_hemisphere about n.
    RAYSTEP_TODO(10, "sample_brdf", "Importance sampling the BRDF");
}

double brdf_pdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_eye,
                const Vec3& to_light) {
    // (1 - t) cos / pi + t p_lobe(wi); GGX's p_lobe = D(h) cos(theta_h) / (4 |wi . h|), h on
    // n's side.
    RAYSTEP_TODO(10, "brdf_pdf", "Importance sampling the BRDF");
}

}  // namespace raystep
