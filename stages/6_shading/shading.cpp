// Stage 6: lights and the local model. Handout: docs/stage6.md. Use your stage-1 functions
// (dot, length, normalize) here.

#include "stages/6_shading/shading.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "base/errors/not_implemented.h"
#include "stages/1_vectors/vectors.h"

namespace raystep {

double attenuation(const Attenuation& attenuation, double distance) {
    // att = constant + linear d + quadratic d^2: the number a point light's colour is divided
    // by at distance d. (1, 0, 0), the default, means no falloff at all.
    RAYSTEP_TODO(6, "attenuation", "Lights and attenuation");
}

LightSample sample_light(const PointLight& light, const Vec3& point) {
    // The vector from the point to the light gives both: distance d = |light - point| and the
    // unit direction L = (light - point) / d. The intensity is colour / att(d).
    // A point at the light has no direction to it: throw std::domain_error.
    RAYSTEP_TODO(6, "sample_light", "Lights and attenuation");
}

LightSample sample_light(const DirectionalLight& light) {
    // L is the light's direction made unit length; the light is infinitely far away, so the
    // distance is infinity, and it is never attenuated: the intensity is its colour.
    RAYSTEP_TODO(6, "sample_light", "Lights and attenuation");
}

Color blinn_phong(const Material& material, const SurfacePoint& point, const LightSample& light) {
    // With N the shading normal, L the light's direction, V the direction to the eye:
    //   H = normalize(L + V),  I = intensity (Kd max(N . L, 0) + Ks max(N . H, 0)^s).
    // N . L <= 0 means the light is behind the surface: return black, the highlight included.
    // L + V = 0 (the eye exactly opposite the light) has no half vector: count N . H as 0.
    // Shininess 0 means max(N . H, 0)^0 = 1, also when N . H = 0 (std::pow(0, 0) is 1).
    RAYSTEP_TODO(6, "blinn_phong", "Blinn-Phong");
}

Color local_shading(const Material& material, const SurfacePoint& point,
                    const std::vector<LightSample>& visible_lights) {
    // I = A + E + the sum of blinn_phong over the lights that reach the point. Ambient and
    // emission are there even where no light reaches: a shadow is dark, not black.
    RAYSTEP_TODO(6, "local_shading", "The local model");
}

}  // namespace raystep
