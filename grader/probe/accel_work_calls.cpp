// Stage 4's calls that only the grader's probe has: a structure handed back as data (its nodes or
// cells), for the grader to check and walk itself; and the timed workloads, whose time the grader
// takes from the kernel, outside this process (docs/instructor.md, "What student code can touch").
// The structure's answers themselves are app/probe/accel_calls.cpp's.
//
// A workload answers the base rays `repeat` times, each pass with every ray moved a little by
// numbers drawn for that pass: no ray is asked twice, so a structure that remembers answers gains
// nothing, and only the hits are returned, a checksum against the reference's.

#include "grader/probe/accel_work_calls.h"

#include "app/protocol/structure_json.h"
#include "base/math/portable_random.h"
#include "stages/4_accel/bvh.h"
#include "stages/4_accel/uniform_grid.h"

namespace raystep::probe {

namespace {

// How far each pass moves the base rays: every origin coordinate by up to `origin`, every
// direction component by up to `direction`, drawn from PortableRandom(seed, pass).
struct Jitter {
    std::uint64_t seed = 0;
    double origin = 0.0;
    double direction = 0.0;
};

Jitter jitter_from(const Json& j) {
    const Json& seed = field(j, "seed");
    if (!seed.is_number_unsigned()) throw std::invalid_argument("a seed is a whole number");
    return {seed.get<std::uint64_t>(), number_from(field(j, "origin")),
            number_from(field(j, "direction"))};
}

Vec3 moved(const Vec3& v, double by, PortableRandom& random) {
    return v + by * random.point(1.0);
}

// The base rays `repeat` times, each pass's moved by its own numbers; the number of hits.
template <class Structure>
Json run_workload(const Structure& structure, const Json& a) {
    const std::vector<Ray> rays = rays_from(field(a, "rays"));
    const Jitter jitter = jitter_from(field(a, "jitter"));
    const int repeat = integer_from(field(a, "repeat"));
    std::size_t hits = 0;
    std::vector<Ray> pass_rays = rays;
    for (int pass = 0; pass < repeat; ++pass) {
        PortableRandom random(jitter.seed, static_cast<std::uint64_t>(pass));
        for (std::size_t k = 0; k < rays.size(); ++k) {
            pass_rays[k].origin = moved(rays[k].origin, jitter.origin, random);
            pass_rays[k].direction = moved(rays[k].direction, jitter.direction, random);
        }
        for (const Ray& r : pass_rays)
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
