#include "app/render/shade_hit.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/render/spot_light.h"
#include "app/render/surface_point.h"
#include "base/math/to_text.h"
#include "stages/8_sampling/sampling.h"

namespace raystep {

namespace {

std::string describe(const Ray& ray) {
    return "origin " + to_text(ray.origin) + " direction " + to_text(ray.direction) + " t in [" +
           to_text(ray.t_min) + ", " + to_text(ray.t_max) + "]";
}

// What blocks a shadow ray, for the trace: the nearest blocker, though the render only asks
// whether there is one.
std::string blocker(const RenderScene& render_scene, const Ray& shadow) {
    const std::optional<PrimitiveHit> hit = scene_closest_hit(render_scene, shadow, nullptr);
    if (!hit) return "reaches the light";
    return "blocked by " + std::string(kind_name(hit->kind)) + " " + std::to_string(hit->index) +
           " (line " + std::to_string(attributes_of(render_scene, hit->kind, hit->index).line) +
           ") at t=" + to_text(hit->hit.t);
}

// A light as the trace names it, "point light (line 12)": built only for a trace, never per hit
// of a render.
std::string light_name(const char* kind, std::uint32_t line) {
    return std::string(kind) + " light (line " + std::to_string(line) + ")";
}

// Whether one light reaches the point.
LightReach reach_of(const RenderScene& render_scene, const SurfacePoint& point,
                    const LightSample& light, const char* kind, std::uint32_t line,
                    TraceLog* trace) {
    if (glm::dot(point.normal, light.direction) <= 0.0) {
        if (trace) trace->add(light_name(kind, line) + ": behind the surface, no shadow ray");
        return LightReach::behind;
    }
    const Ray shadow = shadow_ray(point, light, render_scene.ray_offset);
    const bool blocked = scene_occluded(render_scene, shadow);
    if (trace) {
        trace->add(light_name(kind, line) + ": direction " + to_text(light.direction) +
                   " distance " + to_text(light.distance) + " intensity " +
                   to_text(light.intensity));
        trace->add("  shadow ray " + describe(shadow) + ": " + blocker(render_scene, shadow));
    }
    return blocked ? LightReach::blocked : LightReach::reaches;
}

// The diffuse and specular parts of one light's term, each from blinn_phong with the other
// colour zeroed: the trace shows which one a wrong pixel gets wrong.
void trace_terms(const Material& material, const SurfacePoint& point, const LightSample& light,
                 const std::string& name, TraceLog& trace) {
    Material diffuse_only = material;
    diffuse_only.specular = Color(0.0);
    Material specular_only = material;
    specular_only.diffuse = Color(0.0);
    trace.add("  " + name + " diffuse " + to_text(blinn_phong(diffuse_only, point, light)) +
              " specular " + to_text(blinn_phong(specular_only, point, light)));
}

// Stage 8 at the point: each quad light's soft shadow, its samples placed by the scene's
// `lightstratify` (jittered n x n strata, or independent random points). A trace lists every
// shadow ray the stage sends, each light sample that faces the surface.
Color quad_lights_shading(const RenderScene& render_scene, const Material& material,
                          const SurfacePoint& point, RandomStream* light_random, TraceLog* trace) {
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
            if (trace) {
                trace->add("  light sample " + std::to_string(shadow_rays) + ": shadow ray " +
                           describe(shadow) + ": " + blocker(render_scene, shadow));
            }
            ++shadow_rays;
            return blocked;
        };
        if (trace) {
            trace->add(light_name("quad", light.line) + ": " + std::to_string(scene.light_samples) +
                       " samples, " + (scene.light_stratify ? "jittered" : "random"));
        }
        const Color term = quad_light_shading(material, point, light, pattern, scene.light_samples,
                                              *light_random, occluded, render_scene.ray_offset);
        if (trace) {
            trace->add("  " + light_name("quad", light.line) + " term " + to_text(term) + " (" +
                       std::to_string(shadow_rays) + " shadow rays; samples behind the surface " +
                       "send none)");
        }
        sum += term;
    }
    return sum;
}

}  // namespace

ShadedHit shade_hit(const RenderScene& render_scene, const Ray& ray, const PrimitiveHit& hit,
                    RandomStream* light_random, TraceLog* trace, PixelRecord* record) {
    const Scene& scene = *render_scene.scene;
    const ObjectAttributes& attributes = attributes_of(render_scene, hit.kind, hit.index);
    const Material& material = scene.materials[attributes.material];
    const SurfacePoint point = surface_point(render_scene, ray, hit);
    if (trace) {
        trace->add("surface point " + to_text(point.position) + " error " + to_text(point.error) +
                   " normal " + to_text(point.normal) + " shading normal " +
                   to_text(point.shading_normal));
    }

    std::vector<LightSample> visible;
    std::vector<std::string> names;
    const auto consider = [&](const LightSample& sample, const char* kind, std::uint32_t line,
                              bool recorded) {
        const LightReach reach = reach_of(render_scene, point, sample, kind, line, trace);
        if (record && recorded) {
            record->lights.push_back({reach, reach == LightReach::reaches
                                                 ? blinn_phong(material, point, sample)
                                                 : Color(0.0)});
        }
        if (reach != LightReach::reaches) return;
        visible.push_back(sample);
        if (trace) names.push_back(light_name(kind, line));
    };
    for (const PointLight& light : scene.point_lights)
        consider(sample_light(light, point.position), "point", light.line, true);
    for (const DirectionalLight& light : scene.directional_lights)
        consider(sample_light(light), "directional", light.line, true);
    for (const SpotLight& light : scene.spot_lights) {
        const LightSample sample = sample_spot_light(light, point.position);
        if (sample.intensity == Color(0.0)) {
            if (trace)
                trace->add(light_name("spot", light.line) + ": no light here, outside its cone");
            continue;
        }
        consider(sample, "spot", light.line, false);
    }

    Color local = local_shading(material, point, visible);
    local += quad_lights_shading(render_scene, material, point, light_random, trace);
    if (trace) {
        trace->add("shading: ambient " + to_text(material.ambient) + " emission " +
                   to_text(material.emission));
        for (std::size_t k = 0; k < visible.size(); ++k) {
            trace_terms(material, point, visible[k], names[k], *trace);
        }
        trace->add("local colour " + to_text(local));
    }
    if (record) record->local = local;
    return {point, local, material.specular};
}

}  // namespace raystep
