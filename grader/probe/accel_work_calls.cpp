// Stage 4 work calls: build a BVH or a grid over the primitives given and report the primitive
// tests each ray cost, counted by the probe itself (stage3_test_count.h). A workload call answers
// the same rays `repeat` times (with a BVH, a grid, or no structure at all) and returns only a
// checksum: the grader times the whole probe from outside. The structure's answers themselves are
// app/probe/accel_calls.cpp's.

#include "grader/probe/accel_work_calls.h"
#include "grader/probe/stage3_test_count.h"
#include "stages/4_accel/bvh.h"
#include "stages/4_accel/uniform_grid.h"

namespace raystep::probe {

namespace {

// What each ray cost the structure in primitive tests, as the probe counts them (never as the
// structure reports them), and how many rays it answered with a hit or as occluded.
template <class Structure>
Json count_work(const Structure& structure, const Json& a) {
    const bool occluded = a.value("occluded", false);
    Json tests = Json::array();
    std::size_t hits = 0;
    for (const Ray& r : rays_from(a.at("rays"))) {
        const std::uint64_t before = stage3_tests_counted();
        hits += occluded ? structure.occluded(r) : structure.closest_hit(r).has_value();
        tests.push_back(stage3_tests_counted() - before);
    }
    return Json{{"tests", tests}, {"hits", hits}};
}

// The same rays `repeat` times, counting hits so that no work can be optimized away.
template <class Structure>
Json run_workload(const Structure& structure, const Json& a) {
    const std::vector<Ray> rays = rays_from(a.at("rays"));
    const int repeat = a.at("repeat").get<int>();
    std::size_t hits = 0;
    for (int k = 0; k < repeat; ++k) {
        for (const Ray& r : rays)
            hits += structure.closest_hit(r).has_value();
    }
    return hits;
}

// No structure: stage 3's closest_hit over every primitive, the baseline a structure must beat.
struct BruteForce {
    PrimitiveList primitives;
    std::optional<PrimitiveHit> closest_hit(const Ray& ray) const {
        return raystep::closest_hit(ray, primitives);
    }
};

}  // namespace

void add_accel_work_calls(CallTable& table) {
    table["bvh_work"] = [](const Json& a) {
        const Bvh bvh(primitive_list_from(a.at("primitives")), bvh_split_from(a.at("split")));
        return count_work(bvh, a);
    };
    table["grid_work"] = [](const Json& a) {
        const UniformGrid grid(primitive_list_from(a.at("primitives")));
        return count_work(grid, a);
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
