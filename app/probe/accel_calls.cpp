// Stage 4 calls that a structure answers on its own: build a BVH or a grid over the primitives
// given and answer every ray, closest hit or occluded; the slab test on boxes; the grid's
// resolution. `raystep grade` answers a release's public stage-4 cases with them. What a query
// costs in primitive tests is the grader's probe's to count (grader/probe/accel_work_calls.h).

#include <stdexcept>

#include "app/probe/call_table.h"
#include "stages/4_accel/aabb.h"
#include "stages/4_accel/bvh.h"
#include "stages/4_accel/uniform_grid.h"

namespace raystep::probe {

namespace {

// The structure's answers for every ray: its closest hits, or whether each ray is occluded.
template <class Structure>
Json answer_rays(const Structure& structure, const Json& a) {
    const bool occluded = a.value("occluded", false);
    Json answers = Json::array();
    for (const Ray& r : rays_from(a.at("rays"))) {
        if (occluded) {
            answers.push_back(structure.occluded(r));
        } else {
            answers.push_back(primitive_hit(structure.closest_hit(r)));
        }
    }
    return answers;
}

}  // namespace

BvhSplit bvh_split_from(const Json& j) {
    if (j == "sah") return BvhSplit::sah;
    if (j == "median") return BvhSplit::median;
    throw std::invalid_argument("expected a split: sah or median");
}

void add_accel_calls(CallTable& table) {
    table["bvh"] = [](const Json& a) {
        const Bvh bvh(primitive_list_from(a.at("primitives")), bvh_split_from(a.at("split")));
        return answer_rays(bvh, a);
    };
    table["grid"] = [](const Json& a) {
        const UniformGrid grid(primitive_list_from(a.at("primitives")));
        return answer_rays(grid, a);
    };
    table["intersect_aabb"] = [](const Json& a) {
        const Ray r = ray_from(a.at("ray"));
        const Aabb box{vec3_from(a.at("min")), vec3_from(a.at("max"))};
        const std::optional<Interval> inside = intersect_aabb(r, 1.0 / r.direction, box);
        if (!inside) return Json(nullptr);
        return Json{{"enter", number(inside->enter)}, {"exit", number(inside->exit)}};
    };
    table["grid_resolution"] = [](const Json& a) {
        const Aabb box{vec3_from(a.at("min")), vec3_from(a.at("max"))};
        const glm::ivec3 cells = grid_resolution(box, a.at("n").get<std::size_t>());
        return Json::array({cells.x, cells.y, cells.z});
    };
}

}  // namespace raystep::probe
