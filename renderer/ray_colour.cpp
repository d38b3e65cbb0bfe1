#include "renderer/ray_colour.h"

#include <glm/geometric.hpp>

#include "renderer/shade_hit.h"
#include "renderer/solids.h"
#include "stages/9_refraction/refraction.h"

namespace raystep {

std::optional<ShadedHit> background_hit(const Ray& ray, const Color& background) {
    if (background == Color(0.0)) return std::nullopt;
    const Vec3 back = -glm::normalize(ray.direction);
    SurfacePoint point{ray.origin, Vec3(0.0), back, back, back};
    return ShadedHit{point, background, Color(0.0)};
}

Color full_colour(const RenderScene& render_scene, const Ray& eye_ray,
                  const std::optional<PrimitiveHit>& eye_hit, RandomStream* light_random,
                  PixelObserver& observer) {
    const Scene& scene = *render_scene.scene;
    // The eye ray's hit is already known; every later ray is found and shaded here. A later ray
    // of stage 9 may be reflected or refracted: the shade function sees only the ray.
    int rays = 0;
    const auto find = [&](const Ray& ray) {
        if (rays++ == 0) return eye_hit;
        const std::optional<PrimitiveHit> hit = scene_closest_hit(render_scene, ray, nullptr);
        observer.later_ray(rays - 1, ray, hit);
        return hit;
    };
    const auto shade = [&](const Ray& ray, const PrimitiveHit& hit) {
        return shade_hit(render_scene, ray, hit, light_random, observer);
    };

    Color colour;
    if (render_scene.refraction) {
        const MediumShadeFunction shade_medium = [&](const Ray& ray) -> std::optional<MediumHit> {
            const std::optional<PrimitiveHit> hit = find(ray);
            if (!hit) {
                const std::optional<ShadedHit> sky = background_hit(ray, scene.background);
                if (!sky) return std::nullopt;
                return MediumHit{*sky, Color(0.0), Medium{0, 1.0}, false};
            }
            return MediumHit{shade(ray, *hit), material_of(render_scene, *hit).transmission,
                             medium_of(render_scene, *hit), entering(ray, *hit)};
        };
        colour = radiance_with_refraction(shade_medium, eye_ray, render_scene.bounces, {},
                                          scene.schlick_fresnel, render_scene.ray_offset);
    } else {
        const ShadeFunction shade_mirror = [&](const Ray& ray) -> std::optional<ShadedHit> {
            const std::optional<PrimitiveHit> hit = find(ray);
            if (!hit) return background_hit(ray, scene.background);
            return shade(ray, *hit);
        };
        colour = radiance(shade_mirror, eye_ray, render_scene.bounces, render_scene.ray_offset);
    }
    observer.recursion_colour(eye_ray, colour);
    return colour;
}

}  // namespace raystep
