#include "studies/epsilon/epsilon_measure.h"

#include <stdexcept>

#include <glm/geometric.hpp>

#include "base/errors/not_implemented.h"
#include "base/scene/scene_features.h"
#include "base/scene/scene_loader.h"
#include "renderer/render_scene.h"
#include "renderer/surface_point.h"
#include "studies/epsilon/exact_visibility.h"

namespace raystep {

namespace {

PrimitiveRef reference_of(const PrimitiveHit& hit) {
    switch (hit.kind) {
        case PrimitiveKind::sphere:
            return {PrimitiveRef::Kind::sphere, hit.index};
        case PrimitiveKind::triangle:
            return {PrimitiveRef::Kind::triangle, hit.index};
        case PrimitiveKind::plane:
            break;
    }
    return {PrimitiveRef::Kind::plane, hit.index};
}

// What the renderer decides for one light at one point under one offset rule: lit when the light
// is on the surface's front and the shadow ray reaches it.
bool renderer_lights(const RenderScene& render_scene, const SurfacePoint& point,
                     const LightSample& light, const RayOffset& offset) {
    if (glm::dot(point.normal, light.direction) <= 0.0) return false;
    return !scene_occluded(render_scene, shadow_ray(point, light, offset));
}

void score(bool exactly_lit, bool rendered_lit, OffsetErrors& errors) {
    if (exactly_lit && !rendered_lit) ++errors.acne;
    if (!exactly_lit && rendered_lit) ++errors.leaks;
}

void measure_pixels(const Scene& scene, const RenderScene& render_scene,
                    EpsilonSceneResult& result) {
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            const Ray ray = camera_ray(render_scene, i, j);
            const ExactHit exact = exact_first_hit(scene, ray.origin, ray.direction);
            const std::size_t lights = scene.point_lights.size();
            if (!exact.decided) {
                result.undecided += lights;
                continue;
            }
            const std::optional<PrimitiveHit> hit = scene_closest_hit(render_scene, ray, nullptr);
            if (!exact.primitive && !hit) continue;
            if (!exact.primitive || !hit || !(reference_of(*hit) == *exact.primitive)) {
                result.other_hit += lights;
                continue;
            }
            const SurfacePoint point = surface_point(render_scene, ray, *hit);
            for (const PointLight& light : scene.point_lights) {
                const Decided truth =
                    exact_light_reaches(scene, ray.origin, ray.direction, exact, light.position);
                if (truth == Decided::undecided) {
                    ++result.undecided;
                    continue;
                }
                const bool lit = truth == Decided::yes;
                ++(lit ? result.lit : result.shadowed);
                const LightSample sample = sample_light(light, point.position);
                for (std::size_t k = 0; k < result.epsilons.size(); ++k) {
                    const double epsilon = result.epsilons[k];
                    score(lit,
                          renderer_lights(render_scene, point, sample,
                                          {OffsetRule::along_ray, epsilon}),
                          result.along_ray[k]);
                    score(lit,
                          renderer_lights(render_scene, point, sample,
                                          {OffsetRule::along_normal, epsilon}),
                          result.along_normal[k]);
                }
                score(lit,
                      renderer_lights(render_scene, point, sample, {OffsetRule::error_bound, 0.0}),
                      result.error_bound);
            }
        }
    }
}

}  // namespace

EpsilonSceneResult measure_epsilon_scene(const std::filesystem::path& path,
                                         const std::vector<double>& epsilons) {
    const Scene scene = load_scene(path);
    const SceneFeatures features = scene_features(scene);
    if (features.uses_transforms()) {
        throw std::invalid_argument(path.string() +
                                    ": the epsilon study's exact answer models no transforms");
    }
    if (features.point_lights == 0) {
        throw std::invalid_argument(path.string() + ": the epsilon study needs a point light");
    }
    EpsilonSceneResult result;
    result.scene = path.string();
    result.epsilons = epsilons;
    result.along_ray.resize(epsilons.size());
    result.along_normal.resize(epsilons.size());
    try {
        const RenderScene render_scene = prepare_render_scene(scene);
        measure_pixels(scene, render_scene, result);
    } catch (const NotImplemented& stub) {
        result.stopped = stub.what();
    }
    return result;
}

}  // namespace raystep
