// Stage 10: sampling a quad light by solid angle, for next event estimation. Handout:
// docs/stage10.md.

#include <cmath>

#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

LightDirectionSample sample_light_direction(const QuadLight& light, const Vec3& point,
                                            const Vec2& u) {
    const Vec3 on_light = light.corner + u.x * light.edge1 + u.y * light.edge2;
    const Vec3 to_light = on_light - point;
    const double distance2 = dot(to_light, to_light);
    LightDirectionSample sample;
    if (distance2 == 0.0) return sample;
    sample.distance = std::sqrt(distance2);
    sample.direction = to_light / sample.distance;
    // The emitting side is ac x ab; |ac x ab| is the area.
    const Vec3 emitting = cross(light.edge2, light.edge1);
    const double area = length(emitting);
    const double cos_light = -dot(emitting, sample.direction) / area;
    if (cos_light == 0.0) return sample;
    sample.pdf = distance2 / (area * std::abs(cos_light));
    if (cos_light > 0.0) sample.radiance = light.radiance;
    return sample;
}

double light_direction_pdf(const QuadLight& light, const Vec3& point, const Vec3& direction) {
    // The ray point + t direction meets the plane of a + s ab + w ac where n . (x - a) = 0,
    // n = ab x ac; s and w follow from the cross products of the offset q with the edges.
    const Vec3 normal = cross(light.edge1, light.edge2);
    const double facing = dot(normal, direction);
    if (facing == 0.0) return 0.0;
    const double t = dot(normal, light.corner - point) / facing;
    if (!(t > 0.0)) return 0.0;
    const Vec3 q = point + t * direction - light.corner;
    const double normal2 = dot(normal, normal);
    const double s = dot(cross(q, light.edge2), normal) / normal2;
    const double w = dot(cross(light.edge1, q), normal) / normal2;
    if (!(s >= 0.0 && s <= 1.0 && w >= 0.0 && w <= 1.0)) return 0.0;
    // d^2 / (A |cos|) with A |cos| = |n . direction| for a unit direction.
    return t * t / std::abs(facing);
}

}  // namespace raystep
