// Stage 10: the CSE168 course's Phong and GGX BRDFs. Handout: docs/stage10.md.

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

namespace {

// Smith's masking for GGX: 2 / (1 + sqrt(1 + alpha^2 tan^2)), tan^2 = (1 - cos^2) / cos^2.
double smith_g1(double cos_theta, double roughness) {
    const double cos2 = cos_theta * cos_theta;
    const double tan2 = std::max(0.0, 1.0 - cos2) / cos2;
    return 2.0 / (1.0 + std::sqrt(1.0 + roughness * roughness * tan2));
}

Color phong_lobe_value(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_light,
                       const Vec3& to_eye) {
    // 0 where r . wi <= 0 whatever s, as phong_lobe_pdf is (pow(0, 0) is 1); r . wi clamped to
    // 1, which rounding may pass: pow(1 + 1e-16, 1e17) is e^10.
    const Vec3 mirror = reflect(-to_eye, normal);
    const double cos_alpha = std::min(dot(mirror, to_light), 1.0);
    if (!(cos_alpha > 0.0)) return Color(0.0);
    return brdf.specular * (brdf.shininess + 2.0) / (2.0 * glm::pi<double>()) *
           std::pow(cos_alpha, brdf.shininess);
}

Color ggx_lobe_value(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_light,
                     const Vec3& to_eye) {
    const double cos_i = dot(normal, to_light);
    const double cos_o = dot(normal, to_eye);
    const Vec3 half = normalize(to_light + to_eye);
    const double d = ggx_distribution(to_local(frame_around(normal), half), brdf.roughness);
    const double g = smith_g1(cos_i, brdf.roughness) * smith_g1(cos_o, brdf.roughness);
    const Color fresnel =
        brdf.specular + (Color(1.0) - brdf.specular) *
                            std::pow(1.0 - std::clamp(dot(to_light, half), 0.0, 1.0), 5.0);
    return fresnel * (g * d / (4.0 * cos_i * cos_o));
}

}  // namespace

Color evaluate_brdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_light,
                    const Vec3& to_eye) {
    if (!(dot(normal, to_light) > 0.0 && dot(normal, to_eye) > 0.0)) return Color(0.0);
    const Color diffuse = brdf.diffuse / glm::pi<double>();
    if (brdf.model == BrdfModel::phong)
        return diffuse + phong_lobe_value(brdf, normal, to_light, to_eye);
    return diffuse + ggx_lobe_value(brdf, normal, to_light, to_eye);
}

}  // namespace raystep
