#include "studies/epsilon/offset_cost.h"

#include <glm/geometric.hpp>

#include "base/scene/scene_loader.h"
#include "renderer/render_scene.h"
#include "renderer/surface_point.h"
#include "studies/common/bench_timing.h"

namespace raystep {

namespace {

// A primary hit, as the shading of a pixel starts from it.
struct PrimaryHit {
    Ray ray;
    PrimitiveHit hit;
};

// A shadow ray's starting data: the surface point and a light in front of it.
struct ShadowQuery {
    SurfacePoint point;
    LightSample light;
};

constexpr int kRuns = 3;

}  // namespace

std::vector<OffsetRuleCost> measure_offset_costs(const std::filesystem::path& path,
                                                 const std::vector<RayOffset>& offsets,
                                                 double& surface_nanoseconds) {
    const Scene scene = load_scene(path);
    const RenderScene render_scene = prepare_render_scene(scene);

    std::vector<PrimaryHit> hits;
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            const Ray ray = camera_ray(render_scene, i, j);
            if (const auto hit = scene_closest_hit(render_scene, ray, nullptr)) {
                hits.push_back({ray, *hit});
            }
        }
    }

    std::vector<ShadowQuery> queries;
    const double surface_seconds = best_of(kRuns, [&] {
        queries.clear();
        for (const PrimaryHit& primary : hits) {
            const SurfacePoint point = surface_point(render_scene, primary.ray, primary.hit);
            for (const PointLight& light : scene.point_lights) {
                const LightSample sample = sample_light(light, point.position);
                if (glm::dot(point.normal, sample.direction) > 0.0)
                    queries.push_back({point, sample});
            }
        }
    });
    surface_nanoseconds = hits.empty() ? 0.0 : surface_seconds / hits.size() * 1e9;

    std::vector<OffsetRuleCost> costs;
    volatile std::size_t blocked = 0;
    for (const RayOffset& offset : offsets) {
        const double seconds = best_of(kRuns, [&] {
            std::size_t count = 0;
            for (const ShadowQuery& query : queries) {
                count += scene_occluded(render_scene, shadow_ray(query.point, query.light, offset));
            }
            blocked = count;
        });
        costs.push_back({offset, queries.empty() ? 0.0 : seconds / queries.size() * 1e9});
    }
    return costs;
}

}  // namespace raystep
