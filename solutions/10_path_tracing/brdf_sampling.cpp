// Stage 10 reference solution: drawing directions shaped like the BRDF.

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

namespace {

double mean(const Color& c) {
    return (c.x + c.y + c.z) / 3.0;
}

// The density of the specular lobe alone at wi.
double lobe_pdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_eye,
                const Vec3& to_light) {
    if (brdf.model == BrdfModel::phong) {
        const Frame lobe = frame_around(reflect(-to_eye, normal));
        return phong_lobe_pdf(to_local(lobe, to_light), brdf.shininess);
    }
    const Vec3 sum = to_light + to_eye;
    if (dot(sum, sum) == 0.0) return 0.0;  // wi = -wo: no half vector
    // A half vector h and its opposite reflect wo to the same wi; the sampler draws h on n's
    // side only.
    const Vec3 half = dot(sum, normal) < 0.0 ? -normalize(sum) : normalize(sum);
    // The Jacobian of reflecting wo about h: dwh / dwi = 1 / (4 |wi . h|).
    return ggx_half_vector_pdf(to_local(frame_around(normal), half), brdf.roughness) /
           (4.0 * std::abs(dot(to_light, half)));
}

}  // namespace

double specular_probability(const SurfaceBrdf& brdf) {
    const double diffuse = mean(brdf.diffuse);
    const double specular = mean(brdf.specular);
    const double share = diffuse + specular > 0.0 ? specular / (diffuse + specular) : 0.0;
    return brdf.model == BrdfModel::ggx ? std::max(0.25, share) : share;
}

Vec3 sample_brdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_eye, const Vec2& u,
                 double choice) {
    if (choice >= specular_probability(brdf))
        return to_world(frame_around(normal), cosine_hemisphere(u));
    if (brdf.model == BrdfModel::phong)
        return to_world(frame_around(reflect(-to_eye, normal)), phong_lobe(u, brdf.shininess));
    const Vec3 half = to_world(frame_around(normal), ggx_half_vector(u, brdf.roughness));
    return reflect(-to_eye, half);
}

double brdf_pdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_eye,
                const Vec3& to_light) {
    const double t = specular_probability(brdf);
    const double diffuse = std::max(dot(normal, to_light), 0.0) / glm::pi<double>();
    return (1.0 - t) * diffuse + (t > 0.0 ? t * lobe_pdf(brdf, normal, to_eye, to_light) : 0.0);
}

}  // namespace raystep
