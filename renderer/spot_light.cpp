#include "renderer/spot_light.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace raystep {

namespace {

constexpr double kDegreesToRadians = 3.14159265358979323846 / 180.0;

}  // namespace

double spot_falloff(const SpotLight& light, const Vec3& point) {
    const Vec3 outward = point - light.position;
    const double distance = glm::length(outward);
    const double axis_length = glm::length(light.direction);
    // At the light, or an axis of zero length: no direction to compare, no light.
    if (!(distance > 0.0) || !(axis_length > 0.0)) return 0.0;
    const double cosine = glm::dot(outward, light.direction) / (distance * axis_length);
    // Compared as cosines, so a NaN from an overflowing product lands outside the cone.
    if (!(cosine >= std::cos(light.cutoff_degrees * kDegreesToRadians))) return 0.0;
    return std::pow(cosine, light.exponent);
}

LightSample sample_spot_light(const SpotLight& light, const Vec3& point) {
    LightSample sample =
        sample_light(PointLight{light.position, light.color, light.attenuation, light.line}, point);
    sample.intensity *= spot_falloff(light, point);
    return sample;
}

}  // namespace raystep
