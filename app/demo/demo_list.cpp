#include "app/demo/demo_list.h"

#include <stdexcept>

#include "app/demo/demos.h"

namespace raystep {

const std::vector<DemoEntry>& demo_list() {
    static const std::vector<DemoEntry> kDemos = {
        {"ray-directions",
         "stage 2: each camera ray's direction as a colour, perspective and orthographic",
         ray_directions_demo,
         "stage2/perspective-wide.test",
         "rays",
         "",
         {},
         nullptr},
        {"barycentrics",
         "stage 3: barycentric coordinates as RGB on a triangle fan and a quad",
         barycentrics_demo,
         "stage3/triangle-fan.test",
         "barycentric",
         "",
         {},
         nullptr},
        {"watertight",
         "stage 3: a closed mesh far from the origin, watertight test beside a leaking one",
         watertight_demo,
         "demos/watertight.test",
         "shaded",
         "",
         {"triangle",
          "triangle test",
          {"intersect_triangle", "intersect_triangle_halfspaces", "intersect_triangle_projection",
           "intersect_triangle_cramer"}},
         watertight_demo_with},
        {"bvh-cost",
         "stage 4: BVH nodes visited plus triangles tested per pixel, as a heat map",
         bvh_cost_demo,
         "demos/stadium-overview.test",
         "cost",
         "",
         {},
         nullptr},
        {"grid-cost",
         "stage 4: the same for a uniform grid, on the same scale: where a grid loses",
         grid_cost_demo,
         "",
         "",
         "",
         {},
         nullptr},
        {"normal-transform",
         "stage 5: normals by M (wrong) beside M^-T (right) under non-uniform scale",
         normal_transform_demo,
         "demos/normal-transform.test",
         "normal",
         "",
         {},
         nullptr},
        {"shadow-acne",
         "stage 6: shadow acne for shadow-ray offsets epsilon = 0, too small, good, error bound",
         shadow_acne_demo,
         "stage6/acne-scale-1e4.test",
         "shaded",
         "offset=along-ray&epsilon=1e-12",
         {},
         nullptr},
        {"aliasing",
         "stage 8: stripes to the horizon at 1, 4, 16 spp, regular grid (moire) against jittered",
         aliasing_demo,
         "demos/aliasing.test",
         "full",
         "spp=4&pixelsampling=regular",
         {},
         nullptr},
        {"soft-shadows",
         "stage 8: an area light's penumbra with 1 to 8 x 8 light samples, stratified and random",
         soft_shadows_demo,
         "demos/soft-shadows.test",
         "shaded",
         "lightsamples=4&lightstratify=on",
         {},
         nullptr},
        {"refraction",
         "stage 9: a glass cube at n = 1, 1.33, 1.5, 2.4: total internal reflection sets in",
         refraction_demo,
         "demos/glass-cube.test",
         "full",
         "ior=1.5",
         {},
         nullptr},
        {"path-tracing",
         "stage 10: the Cornell box by four estimators at equal samples, and MIS converging",
         path_tracing_demo,
         "stage10/cornell-box.test",
         "full",
         "spp=4",
         {},
         nullptr},
        {"surface-detail",
         "stage 11: face against interpolated normals, bump against normal maps, textures",
         surface_detail_demo,
         "stage11/bumps.test",
         "shaded",
         "",
         {},
         nullptr},
    };
    return kDemos;
}

std::vector<std::string> demo_names() {
    std::vector<std::string> names;
    for (const DemoEntry& demo : demo_list())
        names.emplace_back(demo.name);
    return names;
}

const DemoEntry& find_demo(std::string_view name) {
    for (const DemoEntry& demo : demo_list()) {
        if (demo.name == name) return demo;
    }
    std::string known;
    for (const DemoEntry& demo : demo_list()) {
        known += (known.empty() ? "" : ", ") + std::string(demo.name);
    }
    throw std::invalid_argument("no demo '" + std::string(name) + "'; the demos are " + known);
}

}  // namespace raystep
