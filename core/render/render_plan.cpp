#include "core/render/render_plan.h"

namespace raystep {

bool uses_bvh(const SceneFeatures& features) {
    return features.spheres + features.triangles >= kBvhFromPrimitives;
}

std::vector<int> stages_for_view(const SceneFeatures& features, View view) {
    std::vector<int> stages = {1, 2};
    if (view == View::rays) return stages;
    stages.push_back(3);
    if (uses_bvh(features)) stages.push_back(4);
    if (features.uses_transforms()) stages.push_back(5);
    if (view != View::full) return stages;
    stages.push_back(6);
    if (features.uses_reflection()) stages.push_back(7);
    return stages;
}

}  // namespace raystep
