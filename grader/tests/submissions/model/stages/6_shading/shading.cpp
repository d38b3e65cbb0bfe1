// Stage 6: lights and the local model. Handout: docs/stage6.md.

#include "stages/6_shading/shading.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "stages/1_vectors/vectors.h"

namespace raystep {

double attenuation(const Attenuation& attenuation, double distance) {
    return attenuation.constant + attenuation.linear * distance +
           attenuation.quadratic * distance * distance;
}

LightSample sample_light(const PointLight& light, const Vec3& point) {
    const Vec3 to_light = light.position - point;
    if (to_light == Vec3(0.0)) {
        throw std::domain_error("sample_light: the point is at the light, no direction to it");
    }
    LightSample sample;
    sample.distance = length(to_light);
    sample.direction = normalize(to_light);
    sample.intensity = light.color / attenuation(light.attenuation, sample.distance);
    return sample;
}

LightSample sample_light(const DirectionalLight& light) {
    // The sun: the same direction everywhere, infinitely far, never attenuated
    LightSample sample;
    sample.direction = normalize(light.direction);
    sample.distance = std::numeric_limits<double>::infinity();
    sample.intensity = light.color;
    return sample;
}

Color blinn_phong(const Material& material, const SurfacePoint& point, const LightSample& light) {
    const Vec3& n = point.shading_normal;
    const Vec3& l = light.direction;

    // A light behind the surface adds nothing, its highlight neither (also rejects NaN)
    const double n_dot_l = dot(n, l);
    if (!(n_dot_l > 0.0)) return Color(0.0);

    // The half vector H = normalize(L + V). L + V is zero only when the eye is exactly opposite
    // the light: no direction is halfway, and there is no highlight to show.
    const Vec3 sum = l + point.to_eye;
    const double n_dot_h = sum == Vec3(0.0) ? 0.0 : dot(n, normalize(sum));

    // pow(0, 0) is 1: shininess 0 means a specular term of Ks wherever the light reaches
    const double highlight = std::pow(std::max(n_dot_h, 0.0), material.shininess);
    return light.intensity * (material.diffuse * n_dot_l + material.specular * highlight);
}

Color local_shading(const Material& material, const SurfacePoint& point,
                    const std::vector<LightSample>& visible_lights) {
    // Ambient and emission even where no light reaches: a shadow is dark, not black
    Color color = material.ambient + material.emission;
    for (const LightSample& light : visible_lights) color += blinn_phong(material, point, light);
    return color;
}

}  // namespace raystep
