// raystep demo bvh-cost: where a BVH spends its work, per pixel.

#include "app/demo/cost_figure.h"
#include "app/demo/demos.h"

namespace raystep {

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

}  // namespace raystep
