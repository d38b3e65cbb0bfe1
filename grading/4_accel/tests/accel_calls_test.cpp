// Stage 4's calls as `raystep grade` answers them in process (grading/4_accel/accel_calls.cpp): a
// structure's answers, the same as the reference's brute force on the same rays; the calls that
// count a structure's work belong to the grader's probe alone (grading/4_accel/accel_workloads.h).

#include "base/testing/catch.h"

#include "app/probe/call_reply.h"
#include "app/probe/call_table.h"
#include "base/math/portable_random.h"

namespace raystep {
namespace {

using probe::Json;

TEST_CASE("accel calls: every structure answers as closest_hit does, and no work call is listed") {
    PortableRandom random(0xACC, 0);
    PrimitiveList list;
    for (int k = 0; k < 40; ++k) {
        const Vec3 c = random.point(1.0);
        list.triangles.push_back({c, c + random.point(0.3), c + random.point(0.3)});
    }
    for (int k = 0; k < 10; ++k)
        list.spheres.push_back({random.point(1.0), random.uniform(0.05, 0.2)});
    std::vector<Ray> rays;
    Json ray_list = Json::array();
    for (int k = 0; k < 60; ++k) {
        const Vec3 origin = 3.0 * random.unit_vector();
        rays.push_back({origin, random.point(1.0) - origin});
        ray_list.push_back(probe::ray(rays.back()));
    }
    const probe::CallTable calls = probe::stage_calls();
    for (const char* work : {"bvh_structure", "grid_structure", "bvh_workload", "grid_workload",
                             "brute_force_workload"}) {
        CHECK(calls.count(work) == 0);
    }
    const Json primitives = probe::primitive_list(list);
    const std::vector<grade::ProbeQuery> queries = {
        {"bvh", {{"primitives", primitives}, {"rays", ray_list}, {"split", "sah"}}},
        {"bvh", {{"primitives", primitives}, {"rays", ray_list}, {"split", "median"}}},
        {"grid", {{"primitives", primitives}, {"rays", ray_list}}},
    };
    std::size_t hits = 0;
    for (const grade::ProbeQuery& query : queries) {
        INFO(query.call);
        const grade::ProbeAnswer answer = probe::answer_in_process(calls, query);
        REQUIRE(answer.kind == grade::ProbeAnswer::Kind::result);
        REQUIRE(answer.value.size() == rays.size());
        grade::ProbeQuery occluded = query;
        occluded.args["occluded"] = true;
        const grade::ProbeAnswer blocked = probe::answer_in_process(calls, occluded);
        REQUIRE(blocked.kind == grade::ProbeAnswer::Kind::result);
        for (std::size_t k = 0; k < rays.size(); ++k) {
            CAPTURE(k);
            const std::optional<PrimitiveHit> expected = closest_hit(rays[k], list);
            const std::optional<PrimitiveHit> got = probe::primitive_hit_from(answer.value[k]);
            REQUIRE(got.has_value() == expected.has_value());
            CHECK(blocked.value[k].get<bool>() == expected.has_value());
            if (!got) continue;
            ++hits;
            CHECK(got->index == expected->index);
            CHECK(got->hit.t == expected->hit.t);
        }
    }
    CHECK(hits > 0);
    const grade::ProbeAnswer bad_split = probe::answer_in_process(
        calls, {"bvh", {{"primitives", primitives}, {"rays", ray_list}, {"split", "middle"}}});
    CHECK(bad_split.kind == grade::ProbeAnswer::Kind::threw);
}

}  // namespace
}  // namespace raystep
