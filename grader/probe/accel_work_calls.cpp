// Stage 4's calls that only the grader's probe has: a structure handed back as data (its nodes or
// cells), for the grader to check and walk itself; and the timed workloads, whose time the grader
// takes from the kernel, outside this process (docs/instructor.md, "What student code can touch").
// The structure's answers themselves are app/probe/accel_calls.cpp's.
//
// A workload is the timed walk of timed_walk.h: the base rays and the shadow rays `repeat` times,
// each pass's moved a little by numbers of its own, so that a structure that remembers answers
// gains nothing; it answers with the digest of every answer, which the grader checks against the
// reference's.

#include "grader/probe/accel_work_calls.h"

#include "app/protocol/structure_json.h"
#include "grader/probe/timed_walk.h"
#include "stages/4_accel/bvh.h"
#include "stages/4_accel/uniform_grid.h"

namespace raystep::probe {

namespace {

Jitter jitter_from(const Json& j) {
    const Json& seed = field(j, "seed");
    if (!seed.is_number_unsigned()) throw std::invalid_argument("a seed is a whole number");
    return {seed.get<std::uint64_t>(), number_from(field(j, "origin")),
            number_from(field(j, "direction"))};
}

// The timed walk of timed_walk.h through `structure`: its digest.
template <class Structure>
Json run_workload(const Structure& structure, const Json& a) {
    return timed_walk(structure, rays_from(field(a, "rays")), rays_from(field(a, "shadow_rays")),
                      jitter_from(field(a, "jitter")), integer_from(field(a, "repeat")));
}

// No structure: stage 3's closest_hit over every primitive, the baseline a structure must beat.
struct BruteForce {
    PrimitiveList primitives;
    std::optional<PrimitiveHit> closest_hit(const Ray& ray) const {
        return raystep::closest_hit(ray, primitives);
    }
    bool occluded(const Ray& ray) const { return closest_hit(ray).has_value(); }
};

}  // namespace

void add_accel_work_calls(CallTable& table) {
    table["bvh_structure"] = [](const Json& a) {
        const Bvh bvh(primitive_list_from(a.at("primitives")), bvh_split_from(a.at("split")));
        return bvh_nodes(bvh.nodes());
    };
    table["grid_structure"] = [](const Json& a) {
        const UniformGrid grid(primitive_list_from(a.at("primitives")));
        return uniform_grid_data(grid.cells());
    };
    table["bvh_workload"] = [](const Json& a) {
        const Bvh bvh(primitive_list_from(a.at("primitives")), bvh_split_from(a.at("split")));
        return run_workload(bvh, a);
    };
    table["grid_workload"] = [](const Json& a) {
        const UniformGrid grid(primitive_list_from(a.at("primitives")));
        return run_workload(grid, a);
    };
    table["brute_force_workload"] = [](const Json& a) {
        return run_workload(BruteForce{primitive_list_from(a.at("primitives"))}, a);
    };
}

}  // namespace raystep::probe
