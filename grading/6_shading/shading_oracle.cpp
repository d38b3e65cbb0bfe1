#include "grading/6_shading/shading_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "base/math/unit_roundoff.h"

namespace raystep {

Wide wide_attenuation(const Attenuation& a, Wide distance) {
    return a.constant + a.linear * distance + a.quadratic * distance * distance;
}

WideLightSample wide_point_light(const PointLight& light, const Vec3& point) {
    const WideVec to_light = widen(light.position) - widen(point);
    const Wide distance = glm::length(to_light);
    const WideVec intensity = widen(light.color) / wide_attenuation(light.attenuation, distance);
    return {to_light / distance, distance, intensity, 24 * kWideUnitRoundoff * glm::abs(intensity)};
}

WideLightSample wide_directional_light(const DirectionalLight& light) {
    const WideVec direction = widen(light.direction) / glm::length(widen(light.direction));
    return {direction, std::numeric_limits<Wide>::infinity(), widen(light.color), WideVec(0.0L)};
}

WideColor wide_blinn_phong(const Material& m, const SurfacePoint& p, const LightSample& l) {
    const WideVec n = widen(p.shading_normal);
    const WideVec light = widen(l.direction);
    const Wide n_dot_l = glm::dot(n, light);
    if (!(n_dot_l > 0)) return {WideVec(0.0L), WideVec(0.0L)};
    // L + V = 0, the eye exactly opposite the light: no half vector, N . H counts as 0.
    const WideVec sum = light + widen(p.to_eye);
    const Wide n_dot_h =
        sum == WideVec(0.0L) ? Wide(0) : std::max(glm::dot(n, glm::normalize(sum)), Wide(0));
    const Wide highlight = std::pow(n_dot_h, Wide(m.shininess));
    // Where N . H is 0 or below (the eye behind the shading normal), the highlight is 0^s, exact.
    const Wide highlight_error =
        n_dot_h > 0
            ? highlight * (4 * kUnitRoundoff +
                           (m.shininess == 0 ? 0 : 8 * kUnitRoundoff * m.shininess / n_dot_h))
            : 0;
    const WideVec intensity = widen(l.intensity);
    const WideVec diffuse = widen(m.diffuse);
    const WideVec specular = widen(m.specular);
    const WideVec value = intensity * (diffuse * n_dot_l + specular * highlight);
    const WideVec tolerance = glm::abs(intensity) * (glm::abs(diffuse) * Wide(8 * kUnitRoundoff) +
                                                     glm::abs(specular) * highlight_error) +
                              Wide(4 * kUnitRoundoff) * glm::abs(value);
    return {value, tolerance};
}

WideColor wide_local_shading(const Material& m, const SurfacePoint& p,
                             const std::vector<LightSample>& lights) {
    WideVec value = widen(m.ambient) + widen(m.emission);
    WideVec size = glm::abs(widen(m.ambient)) + glm::abs(widen(m.emission));
    WideVec tolerance(0.0L);
    for (const LightSample& l : lights) {
        const WideColor term = wide_blinn_phong(m, p, l);
        value += term.value;
        size += glm::abs(term.value);
        tolerance += term.tolerance;
    }
    tolerance += Wide(4 * kUnitRoundoff * (lights.size() + 2)) * size;
    return {value, tolerance};
}

}  // namespace raystep
