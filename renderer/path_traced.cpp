#include "renderer/path_traced.h"

#include <glm/geometric.hpp>

#include "renderer/seen_quad_light.h"
#include "renderer/surface_maps.h"
#include "renderer/surface_point.h"
#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

namespace {

SurfaceBrdf surface_brdf(const Material& material) {
    return {material.brdf, material.diffuse, material.specular, material.shininess,
            material.roughness};
}

PathSettings path_settings(const Scene& scene) {
    PathSettings settings;
    settings.max_depth = scene.max_depth == kUnboundedDepth ? kLongestPath : scene.max_depth;
    settings.russian_roulette = scene.russian_roulette;
    settings.sampling = scene.importance_sampling;
    settings.next_event = scene.next_event;
    return settings;
}

// A quad light where a ray meets it: a surface facing the ray that reflects nothing.
PathHit light_hit(const Scene& scene, const Ray& ray, const SeenQuadLight& seen) {
    Vec3 normal = glm::normalize(glm::cross(seen.light->edge1, seen.light->edge2));
    if (glm::dot(normal, ray.direction) > 0.0) normal = -normal;
    PathHit hit;
    hit.point = {ray.origin + seen.t * ray.direction, Vec3(0.0), normal, normal,
                 -glm::normalize(ray.direction)};
    hit.emission = seen.colour;
    hit.light = static_cast<std::size_t>(seen.light - scene.quad_lights.data());
    return hit;
}

}  // namespace

namespace {

// One path of `settings` over the scene, its rays told to `observer`.
Color path_colour(const RenderScene& render_scene, const Ray& ray, const PathSettings& settings,
                  RandomStream& random, PixelObserver& observer) {
    const Scene& scene = *render_scene.scene;
    PathScene path;
    path.lights = scene.quad_lights;
    path.offset = render_scene.ray_offset;
    path.occluded = [&](const Ray& shadow) {
        const bool blocked = scene_occluded(render_scene, shadow);
        observer.path_shadow_ray(shadow, blocked);
        return blocked;
    };
    int rays = 0;
    path.intersect = [&](const Ray& next) -> std::optional<PathHit> {
        const std::optional<PrimitiveHit> hit = scene_closest_hit(render_scene, next, nullptr);
        const std::optional<SeenQuadLight> seen = seen_quad_light(scene, next, hit);
        observer.path_ray(rays++, next, hit, seen ? &*seen : nullptr);
        if (seen) return light_hit(scene, next, *seen);
        if (!hit) return std::nullopt;
        PathHit surface;
        surface.point = surface_point(render_scene, next, *hit);
        const Material material = mapped_material(render_scene, next, *hit,
                                                  material_of(render_scene, *hit), surface.point);
        surface.brdf = surface_brdf(material);
        surface.emission = material.emission;
        return surface;
    };
    return path_radiance(ray, path, settings, random);
}

}  // namespace

Color path_traced_colour(const RenderScene& render_scene, const Ray& ray, RandomStream& random,
                         PixelObserver& observer) {
    return path_colour(render_scene, ray, path_settings(*render_scene.scene), random, observer);
}

Color path_traced_indirect_colour(const RenderScene& render_scene, const Ray& ray,
                                  RandomStream& random, PixelObserver& observer) {
    const PathSettings settings = path_settings(*render_scene.scene);
    if (settings.max_depth >= 0 && settings.max_depth < 2) return Color(0.0);
    PathSettings direct = settings;
    direct.max_depth = 1;
    RandomStream same = random;
    const Color whole = path_colour(render_scene, ray, settings, random, observer);
    return whole - path_colour(render_scene, ray, direct, same, unobserved());
}

}  // namespace raystep
