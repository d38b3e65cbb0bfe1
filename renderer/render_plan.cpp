#include "renderer/render_plan.h"

namespace raystep {

std::size_t bvh_primitives(const SceneFeatures& features) {
    return features.spheres - features.transformed_spheres + features.triangles -
           features.transformed_triangles;
}

bool uses_bvh(const SceneFeatures& features) {
    return bvh_primitives(features) >= kBvhFromPrimitives;
}

bool uses_instance_bvh(const SceneFeatures& features) {
    return features.instances >= kBvhFromPrimitives ||
           features.largest_instance >= kBvhFromPrimitives;
}

std::vector<int> stages_for_view(const SceneFeatures& features, View view) {
    std::vector<int> stages = {1, 2};
    if (view == View::rays) return stages;
    stages.push_back(3);
    if (uses_bvh(features) || uses_instance_bvh(features)) stages.push_back(4);
    if (features.uses_transforms()) stages.push_back(5);
    if (view == View::uv || view == View::tangent) {
        stages.push_back(11);
        return stages;
    }
    if (view != View::shaded && view != View::full && view != View::indirect) return stages;
    stages.push_back(6);
    // A path-traced full or indirect view: stage 10's paths (over stage 6's spawn_ray), stage 8
    // only for the pixel's samples; the paths neither mirror nor refract.
    if ((view == View::full || view == View::indirect) && features.path_traced) {
        if (features.samples_per_pixel > 1) stages.push_back(8);
        stages.push_back(10);
        if (features.uses_surface_detail()) stages.push_back(11);
        return stages;
    }
    // Stage 9 reflects with stage 7's reflected_ray, so a transmitting scene runs stage 7 too.
    if (view == View::full && (features.uses_reflection() || features.uses_refraction())) {
        stages.push_back(7);
    }
    if (features.uses_sampling()) stages.push_back(8);
    if (view == View::full && features.uses_refraction()) stages.push_back(9);
    // Shading reads the smooth or mapped normal and the texture; the geometry keeps the flat
    // normal.
    if (features.uses_surface_detail()) stages.push_back(11);
    return stages;
}

}  // namespace raystep
