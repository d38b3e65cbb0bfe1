#include "renderer/seen_quad_light.h"

#include <glm/geometric.hpp>

#include "renderer/nearest_hit.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

std::optional<SeenQuadLight> seen_quad_light(const Scene& scene, const Ray& ray,
                                             const std::optional<PrimitiveHit>& hit) {
    if (scene.dialect != SceneDialect::cse168) return std::nullopt;
    std::optional<SeenQuadLight> nearest;
    Ray cut = cut_at(ray, hit);
    for (const QuadLight& light : scene.quad_lights) {
        const Vec3 a = light.corner;
        const Vec3 b = a + light.edge1;
        const Vec3 c = b + light.edge2;
        const Vec3 d = a + light.edge2;
        std::optional<Hit> met = intersect_triangle(cut, {a, b, c});
        if (!met) met = intersect_triangle(cut, {a, c, d});
        if (!met) continue;
        const Vec3 emitting_side = glm::cross(light.edge2, light.edge1);
        const bool front = glm::dot(ray.direction, emitting_side) < 0.0;
        nearest = SeenQuadLight{&light, met->t, front ? light.radiance : Color(0.0)};
        cut.t_max = met->t;
    }
    return nearest;
}

}  // namespace raystep
