#include "app/demo/cost_figure.h"

#include <algorithm>
#include <cmath>

#include "app/demo/demo_scene.h"
#include "renderer/tile_renderer.h"

namespace raystep {

namespace {

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

}  // namespace

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

}  // namespace raystep
