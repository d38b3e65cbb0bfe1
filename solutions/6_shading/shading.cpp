// Stage 6 reference solution: lights and the local model.

#include "stages/6_shading/shading.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "base/math/to_text.h"
#include "stages/1_vectors/vectors.h"

namespace raystep {

double attenuation(const Attenuation& attenuation, double distance) {
    return attenuation.constant + attenuation.linear * distance +
           attenuation.quadratic * distance * distance;
}

LightSample sample_light(const PointLight& light, const Vec3& point) {
    const Vec3 to_light = light.position - point;
    if (to_light == Vec3(0.0)) {
        throw std::domain_error("sample_light: the point " + to_text(point) +
                                " is at the light, which has no direction from it");
    }
    const double distance = length(to_light);
    return {normalize(to_light), distance, light.color / attenuation(light.attenuation, distance)};
}

LightSample sample_light(const DirectionalLight& light) {
    return {normalize(light.direction), std::numeric_limits<double>::infinity(), light.color};
}

Color blinn_phong(const Material& material, const SurfacePoint& point, const LightSample& light) {
    const Vec3& n = point.shading_normal;
    const Vec3& l = light.direction;

    // A light behind the surface adds nothing, its highlight neither; rejects a NaN N . L too
    const double n_dot_l = dot(n, l);
    if (!(n_dot_l > 0.0)) return Color(0.0);

    // The half vector. L + V is zero only when the eye is exactly opposite the light, which a
    // lit point shows only through a shading normal turned away from the eye. No direction lies
    // halfway, and there is no highlight to show: the mirror image of L about N is far from
    // V = -L (it equals -L only when N . L = 0).
    const Vec3 half_sum = l + point.to_eye;
    const double n_dot_h = half_sum == Vec3(0.0) ? 0.0 : dot(n, normalize(half_sum));

    // pow(0, 0) = 1, as std::pow defines it: x^0 = 1 for every x > 0, so 1 is the limit as N . H
    // falls to 0, and shininess 0 means a specular term of Ks everywhere a light reaches. Any
    // other choice makes the term jump where N . H reaches 0, and NaN would blacken every
    // "specular 0 shininess 0" material of the CSE167 scenes (0 * NaN is NaN).
    const double highlight = std::pow(std::max(n_dot_h, 0.0), material.shininess);
    return light.intensity * (material.diffuse * n_dot_l + material.specular * highlight);
}

Color local_shading(const Material& material, const SurfacePoint& point,
                    const std::vector<LightSample>& visible_lights) {
    Color color = material.ambient + material.emission;
    for (const LightSample& light : visible_lights) {
        color += blinn_phong(material, point, light);
    }
    return color;
}

}  // namespace raystep
