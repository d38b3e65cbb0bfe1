#include "renderer/shade_hit.h"

#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "base/errors/input_error.h"
#include "base/math/to_text.h"
#include "renderer/local_model.h"
#include "renderer/polygon_irradiance.h"
#include "renderer/spot_light.h"
#include "renderer/surface_maps.h"
#include "renderer/surface_point.h"
#include "stages/8_sampling/sampling.h"

namespace raystep {

namespace {

// Whether one light reaches the point: one in front of the surface sends a shadow ray.
LightStep light_step(const RenderScene& render_scene, const SurfacePoint& point,
                     const LightSample& light, LightKind kind, std::uint32_t line) {
    if (glm::dot(point.normal, light.direction) <= 0.0)
        return {kind, line, light, LightReach::behind, std::nullopt};
    const Ray shadow = shadow_ray(point, light, render_scene.ray_offset);
    const bool blocked = scene_occluded(render_scene, shadow);
    return {kind, line, light, blocked ? LightReach::blocked : LightReach::reaches, shadow};
}

// A point or spot light sampled from the point. One exactly at the point has no direction from it
// (stage 6's sample_light throws): the scene put a light on a surface that a ray sees, which is
// reported on the light's line.
template <class SampleLight>
LightSample sampled_from(const Scene& scene, std::uint32_t line, const SurfacePoint& point,
                         const SampleLight& sample_light) {
    try {
        return sample_light();
    } catch (const std::domain_error& error) {
        throw InputError(scene.path, static_cast<int>(line),
                         "the light is at " + to_text(point.position) +
                             ", a point of a surface that a ray sees, where it has no direction "
                             "to light it by (" +
                             error.what() + "); move it off the surface");
    }
}

// The CSE168 dialect's direct integrator at the point: stage 8's light samples, each shaded by the
// course's Phong lobe (local_model.h) where its shadow ray reaches the light, as
// quad_light_shading does with Blinn-Phong.
Color sampled_phong_lobes(const RenderScene& render_scene, const Material& material,
                          const SurfacePoint& point, const QuadLight& light, SamplePattern pattern,
                          RandomStream& random, const OccludedFunction& occluded) {
    const int count = render_scene.scene->light_samples;
    Color sum(0.0);
    for (const Vec2& u : samples(pattern, count, random)) {
        const LightSample sample = sample_quad_light(light, point.position, u, count);
        // Behind the surface, or from the light's dark side: nothing to add, no ray to trace.
        if (!(glm::dot(point.shading_normal, sample.direction) > 0.0) ||
            sample.intensity == Color(0.0)) {
            continue;
        }
        if (occluded(shadow_ray(point, sample, render_scene.ray_offset))) continue;
        sum += phong_lobe_term(material, point, sample);
    }
    return sum;
}

// Stage 8 at the point: each quad light's soft shadow, its samples placed by the scene's
// `lightstratify` (jittered n x n strata, or independent random points). In the CSE168 dialect
// the samples are shaded by the course's Phong lobe, and `integrator analyticdirect` integrates
// each light exactly instead, unshadowed and diffuse only, as the course's integrator does.
Color quad_lights_shading(const RenderScene& render_scene, const Material& material,
                          const SurfacePoint& point, RandomStream* light_random,
                          PixelObserver& observer) {
    const Scene& scene = *render_scene.scene;
    Color sum(0.0);
    if (scene.quad_lights.empty()) return sum;
    if (!light_random) throw std::logic_error("shade_hit: quad lights need a random stream");
    const SamplePattern pattern =
        scene.light_stratify ? SamplePattern::jittered : SamplePattern::random;
    for (const QuadLight& light : scene.quad_lights) {
        int shadow_rays = 0;
        const OccludedFunction occluded = [&](const Ray& shadow) {
            const bool blocked = scene_occluded(render_scene, shadow);
            observer.quad_light_sample(shadow_rays++, shadow, blocked);
            return blocked;
        };
        observer.quad_light_starts(light);
        Color term;
        if (scene.integrator == Integrator::analyticdirect) {
            term = material.diffuse / glm::pi<double>() * light.radiance *
                   quad_light_irradiance(light, point.position, point.shading_normal);
        } else if (scene.dialect == SceneDialect::cse168) {
            term = sampled_phong_lobes(render_scene, material, point, light, pattern, *light_random,
                                       occluded);
        } else {
            term = quad_light_shading(material, point, light, pattern, scene.light_samples,
                                      *light_random, occluded, render_scene.ray_offset);
        }
        observer.quad_light_ends(light, term, shadow_rays);
        sum += term;
    }
    return sum;
}

}  // namespace

ShadedHit shade_hit(const RenderScene& render_scene, const Ray& ray, const PrimitiveHit& hit,
                    RandomStream* light_random, PixelObserver& observer) {
    const Scene& scene = *render_scene.scene;
    SurfacePoint point = surface_point(render_scene, ray, hit);
    const Material material =
        mapped_material(render_scene, ray, hit, material_of(render_scene, hit), point);
    observer.surface(point, material);

    std::vector<LightSample> reaching;
    const auto consider = [&](const LightSample& sample, LightKind kind, std::uint32_t line) {
        const LightStep step = light_step(render_scene, point, sample, kind, line);
        observer.light(step);
        if (step.reach == LightReach::reaches) reaching.push_back(sample);
    };
    for (const PointLight& light : scene.point_lights) {
        const LightSample sample = sampled_from(
            scene, light.line, point, [&] { return sample_light(light, point.position); });
        consider(sample, LightKind::point, light.line);
    }
    for (const DirectionalLight& light : scene.directional_lights)
        consider(sample_light(light), LightKind::directional, light.line);
    for (const SpotLight& light : scene.spot_lights) {
        const LightSample sample = sampled_from(
            scene, light.line, point, [&] { return sample_spot_light(light, point.position); });
        if (sample.intensity == Color(0.0)) {
            observer.spot_light_outside_cone(light.line);
            continue;
        }
        consider(sample, LightKind::spot, light.line);
    }

    Color local = local_colour(scene.dialect, material, point, reaching);
    local += quad_lights_shading(render_scene, material, point, light_random, observer);
    observer.local_colour(reaching, local);
    // In the CSE168 dialect specular is a lobe, never a mirror, even where stage 9's recursion runs
    // for something that transmits.
    const Color reflectance =
        scene.dialect == SceneDialect::cse168 ? Color(0.0) : material.specular;
    return {point, local, reflectance};
}

}  // namespace raystep
