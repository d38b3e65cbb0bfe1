#include "renderer/local_model.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace raystep {

Color phong_lobe_term(const Material& material, const SurfacePoint& point,
                      const LightSample& light) {
    const Vec3& n = point.shading_normal;
    const double cos_light = glm::dot(n, light.direction);
    if (!(cos_light > 0.0)) return Color(0.0);
    const Vec3 mirror = 2.0 * glm::dot(n, point.to_eye) * n - point.to_eye;
    // The lobe is 0 where R . L <= 0, whatever s: pow(0, 0) would make a lobe of s = 0 the whole
    // sky. R . L is clamped to 1, which rounding may pass: pow(1 + 1e-16, 1e17) is e^10.
    const double cos_lobe = std::min(glm::dot(mirror, light.direction), 1.0);
    const double lobe =
        cos_lobe > 0.0 ? (material.shininess + 2.0) / 2.0 * std::pow(cos_lobe, material.shininess)
                       : 0.0;
    return light.intensity * cos_light * (material.diffuse + material.specular * lobe);
}

Color light_term(SceneDialect dialect, const Material& material, const SurfacePoint& point,
                 const LightSample& light) {
    return dialect == SceneDialect::cse168 ? phong_lobe_term(material, point, light)
                                           : blinn_phong(material, point, light);
}

Color local_colour(SceneDialect dialect, const Material& material, const SurfacePoint& point,
                   const std::vector<LightSample>& visible_lights) {
    if (dialect == SceneDialect::cse167) return local_shading(material, point, visible_lights);
    Color colour = material.ambient + material.emission;
    for (const LightSample& light : visible_lights)
        colour += phong_lobe_term(material, point, light);
    return colour;
}

}  // namespace raystep
