// Stage 8: area lights and soft shadows. Handout: docs/stage8.md. Use your stage-1 vector
// functions and your stage-6 blinn_phong and shadow_ray here.

#include "base/errors/not_implemented.h"
#include "stages/8_sampling/sampling.h"

namespace raystep {

LightSample sample_quad_light(const QuadLight& light, const Vec3& point, const Vec2& u,
                              int sample_count) {
    // y = a + u.x ab + u.y ac; L = (y - x) / d with d = |y - x|;
    //   intensity = radiance A cos(theta_l) / (pi d^2 sample_count),
    // A = |ab x ac|, cos(theta_l) = max((ab x ac) . L / A, 0): the light shines from its
    // ac x ab side only.
    RAYSTEP_TODO(8, "sample_quad_light", "Area lights");
}

Color quad_light_shading(const Material& material, const SurfacePoint& point,
                         const QuadLight& light, SamplePattern pattern, int sample_count,
                         RandomStream& random, const OccludedFunction& occluded,
                         const RayOffset& offset) {
    // For each u of samples(pattern, sample_count, random): the light sample at u; skip it when
    // N . L <= 0; otherwise add blinn_phong(material, point, sample) when
    // occluded(shadow_ray(point, sample, offset)) is false.
    RAYSTEP_TODO(8, "quad_light_shading", "Soft shadows");
}

}  // namespace raystep
