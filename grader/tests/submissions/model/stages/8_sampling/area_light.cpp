// Stage 8: a quad light as many point lights, and its soft shadow. Handout: docs/stage8.md.

#include <cmath>
#include <stdexcept>

#include "base/math/to_text.h"
#include "stages/1_vectors/vectors.h"
#include "stages/8_sampling/sampling.h"

namespace raystep {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

LightSample sample_quad_light(const QuadLight& light, const Vec3& point, const Vec2& u,
                              int sample_count) {
    const Vec3 on_light = light.corner + u.x * light.edge1 + u.y * light.edge2;
    const Vec3 to_light = on_light - point;
    if (to_light == Vec3(0.0)) {
        throw std::domain_error("sample_quad_light: the point " + to_text(point) +
                                " is on the light, which has no direction from it");
    }
    const double distance = length(to_light);
    const Vec3 direction = to_light / distance;

    // ab x ac is the area vector: its length the area, and it points away from the emitting
    // side ac x ab. The light leaves towards the point along -L, so cos(theta_l) is
    // (ac x ab) . (-L) / A = (ab x ac) . L / A, and the A cancels.
    const double area_cos = std::max(dot(cross(light.edge1, light.edge2), direction), 0.0);
    const double solid_angle_share = area_cos / (kPi * distance * distance * sample_count);
    return {direction, distance, light.radiance * solid_angle_share};
}

Color quad_light_shading(const Material& material, const SurfacePoint& point,
                         const QuadLight& light, SamplePattern pattern, int sample_count,
                         RandomStream& random, const OccludedFunction& occluded,
                         const RayOffset& offset) {
    Color sum(0.0);
    for (const Vec2& u : samples(pattern, sample_count, random)) {
        const LightSample sample = sample_quad_light(light, point.position, u, sample_count);
        // Behind the surface, or from the light's dark side: nothing to add, no ray to trace.
        if (!(dot(point.shading_normal, sample.direction) > 0.0) ||
            sample.intensity == Color(0.0)) {
            continue;
        }
        if (occluded(shadow_ray(point, sample, offset))) continue;
        sum += blinn_phong(material, point, sample);
    }
    return sum;
}

}  // namespace raystep
