// The demos of stage 4: where a structure spends its work, per pixel, on one figure that the
// BVH's and the grid's demos share.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "app/demo/demo_scene.h"
#include "app/demo/demos.h"
#include "renderer/tile_renderer.h"
#include "stages/4_accel/uniform_grid.h"

namespace raystep {

namespace {

/// What one ray costs a structure: nodes or cells visited plus primitives tested.
using RayCost = std::function<std::uint64_t(const Ray& ray)>;

/// Builds the structure for a scene and returns its RayCost, which owns it.
using CostStructure = std::function<RayCost(const RenderScene& render_scene)>;

// The top of the scale: above the dearest pixel of either scene in either structure (the grid's
// rays through the stadium's four bunny cells test some 19,000 triangles each, and walk cells
// besides), so that no demo clips, and a power of ten so that the bar ends on a number.
constexpr double kCostScaleTop = 1e5;

DemoPanel cost_panel(const std::string& scene_path, const std::string& name, const PanelSize& panel,
                     const CostStructure& structure, const LogHeatScale& scale) {
    const Scene scene = load_demo_scene(scene_path, panel);
    const RenderScene render_scene = prepare_render_scene(scene);
    const RayCost cost = structure(render_scene);

    // Each pixel's cost, exact in a float's 24 bits up to 16 million
    const Image costs = render_pixels(
        scene.width, scene.height,
        [&](int i, int j) {
            return Color(static_cast<double>(cost(camera_ray(render_scene, i, j))));
        },
        0);

    // The heat map, and the numbers for the caption
    Image heat(costs.width(), costs.height());
    double total = 0.0;
    double most = 0.0;
    for (int j = 0; j < costs.height(); ++j) {
        for (int i = 0; i < costs.width(); ++i) {
            const double value = costs.at(i, j).r;
            total += value;
            most = std::max(most, value);
            heat.set(i, j, log_heat_colour(value, scale));
        }
    }
    const double mean = total / (static_cast<double>(costs.width()) * costs.height());
    return {name + ": mean " + thousands(static_cast<std::uint64_t>(std::lround(mean))) + ", max " +
                thousands(static_cast<std::uint64_t>(most)),
            std::move(heat)};
}

// The figure of a cost demo: stage 4's bunny close up beside the bunny in a stadium, each pixel
// coloured by what its camera ray cost `structure`, on a logarithmic scale from 1 to 10^5 that is
// the same in every cost demo, so that their images compare colour for colour. Each caption gives
// the mean and the largest cost per pixel.
DemoFigure cost_figure(const DemoSize& size, const std::string& title,
                       const CostStructure& structure) {
    const PanelSize panel = panel_size(size, 2, true);
    DemoFigure figure;
    figure.title = title;
    figure.scale = LogHeatScale{kCostScaleTop, "steps per pixel (log)"};
    figure.panels.push_back(
        cost_panel("stage4/bunny.test", "bunny", panel, structure, *figure.scale));
    figure.panels.push_back(
        cost_panel("demos/stadium-overview.test", "in a stadium", panel, structure, *figure.scale));
    return figure;
}

}  // namespace

// raystep demo bvh-cost: where a BVH spends its work, per pixel.

DemoFigure bvh_cost_demo(const DemoSize& size) {
    // The renderer's own BVH (SAH, stage 4) and its count of the work, as in `--view cost`, but on
    // the fixed scale that the grid's demo shares.
    const CostStructure bvh = [](const RenderScene& render_scene) -> RayCost {
        return [&render_scene](const Ray& ray) {
            TraversalStats stats;
            scene_closest_hit(render_scene, ray, &stats);
            return stats.nodes + stats.primitive_tests;
        };
    };
    return cost_figure(size, "BVH cost: nodes visited + triangles tested", bvh);
}

// raystep demo grid-cost: where a uniform grid spends its work, per pixel.

DemoFigure grid_cost_demo(const DemoSize& size) {
    // Stage 4's uniform grid over the scene's spheres and triangles (the cost demos' scenes have
    // nothing else), walked by 3D-DDA. In the stadium it cannot adapt: the bunny falls into four
    // cells of some 19,000 triangles each, and every ray that enters them tests them all.
    const CostStructure grid = [](const RenderScene& render_scene) -> RayCost {
        auto built = std::make_shared<const UniformGrid>(render_scene.primitives);
        return [built](const Ray& ray) {
            TraversalStats stats;
            built->closest_hit(ray, &stats);
            return stats.nodes + stats.primitive_tests;
        };
    };
    return cost_figure(size, "Uniform grid cost: cells visited + triangles tested", grid);
}

}  // namespace raystep
