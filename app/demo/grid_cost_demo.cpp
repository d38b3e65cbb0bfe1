// raystep demo grid-cost: where a uniform grid spends its work, per pixel.

#include <memory>

#include "app/demo/cost_figure.h"
#include "app/demo/demos.h"
#include "stages/4_accel/uniform_grid.h"

namespace raystep {

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
