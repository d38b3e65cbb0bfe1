// The grader's probe answers every stage-4 call of its protocol (grader/probe/README.md): the
// structure's answers, which grading/4_accel/accel_calls.cpp gives it as it gives `raystep grade`,
// and the structure as data and the timed workloads, which it alone has
// (grading/4_accel/accel_workloads.cpp); and the timed walk's digest, which hangs on a seed each
// grade draws anew.

#include "grading/4_accel/accel_workloads.h"

#include <set>

#include "base/testing/catch.h"
#include "grader/grade/check_definition.h"
#include "grader/grade/probe_client.h"
#include "grading/4_accel/stage4_structure.h"
#include "grading/4_accel/structure_json.h"
#include "grading/4_accel/timed_walk.h"

using namespace raystep;

TEST_CASE("the reference probe answers every stage-4 call of the protocol") {
    PrimitiveList list;
    list.triangles.push_back({{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}});
    list.spheres.push_back({{0, 0, 3}, 0.5});
    const probe::Json rays = probe::Json::array({probe::ray({{0, 0, -5}, {0, 0, 1}})});
    const probe::Json scene = {{"primitives", probe::primitive_list(list)},
                               {"rays", rays},
                               {"split", "sah"},
                               {"shadow_rays", rays},
                               {"repeat", 2},
                               {"jitter", {{"seed", 9}, {"origin", 1e-3}, {"direction", 1e-4}}}};
    const std::vector<grade::ProbeQuery> queries = {
        {"bvh", scene},
        {"grid", scene},
        {"bvh_structure", scene},
        {"grid_structure", scene},
        {"bvh_workload", scene},
        {"grid_workload", scene},
        {"brute_force_workload", scene},
        {"intersect_aabb",
         {{"ray", rays[0]}, {"min", probe::vec3({-1, -1, -1})}, {"max", probe::vec3({1, 1, 1})}}},
        {"grid_resolution",
         {{"min", probe::vec3({0, 0, 0})}, {"max", probe::vec3({1, 1, 1})}, {"n", 9}}},
    };
    const grade::ProbeSession session =
        grade::ask_probe(RAYSTEP_REFERENCE_PROBE, queries, grade::ProbeRunLimits{});
    REQUIRE(session.answers.size() == queries.size());
    for (std::size_t k = 0; k < queries.size(); ++k) {
        INFO(queries[k].call);
        CHECK(session.answers[k].kind == grade::ProbeAnswer::Kind::result);
    }
    // The triangle at t = 5 is the first hit, for the structures and the work counts alike
    CHECK(probe::primitive_hit_from(session.answers[0].value[0])->hit.t == 5.0);
    CHECK(probe::primitive_hit_from(session.answers[1].value[0])->hit.t == 5.0);
    // The structures as data are the reference's, whole
    CHECK_FALSE(grade::bvh_problem(probe::bvh_nodes_from(session.answers[2].value), list));
    CHECK_FALSE(grade::grid_problem(probe::uniform_grid_data_from(session.answers[3].value), list));
    // Two passes of the ray, moved a little each time: the digest of the triangle's hit and the
    // occlusion, both times, as the grader's own walk of the reference finds it
    const probe::Jitter jitter{9, 1e-3, 1e-4};
    const std::vector<Ray> ray_list = probe::rays_from(rays);
    CHECK(session.answers[4].value ==
          probe::timed_walk(Bvh(list, BvhSplit::sah), ray_list, ray_list, jitter, 2));
    CHECK(session.answers[5].value ==
          probe::timed_walk(UniformGrid(list), ray_list, ray_list, jitter, 2));
    CHECK(session.answers[4].value !=
          probe::timed_walk(Bvh(list, BvhSplit::sah), ray_list, ray_list, jitter, 1));
    CHECK(session.answers[7].value.at("enter") == 4.0);
    CHECK(session.answers[8].value == probe::Json::array({3, 3, 3}));
}

namespace {

// Two passes through the SAH BVH, with the jitter the tests below check against; no scene yet.
probe::WorkloadQuestion two_passes() {
    probe::WorkloadQuestion question;
    question.split = "sah";
    question.jitter = {9, 1e-3, 1e-4};
    question.repeat = 2;
    return question;
}

// `named`, its scene sent as data instead: the scene the probe would make from the name.
probe::WorkloadQuestion sent_as_data(probe::WorkloadQuestion named, const grade::WorkScene& scene) {
    named.walls.reset();
    named.speed.reset();
    named.primitives = scene.primitives;
    named.rays = scene.rays;
    named.shadow_rays = grade::shadow_rays(scene);
    return named;
}

// A workload's arguments, for the probe to be asked by the calls' names: the workloads' answers
// are the probe's own objects, not this program's.
probe::Json args(const probe::WorkloadQuestion& question) {
    return probe::JsonCodec<probe::WorkloadQuestion>::write(question);
}

}  // namespace

TEST_CASE("a walls scene the probe makes itself is walked as the same scene sent as data") {
    const grade::WorkScene scene = grade::walls_scene(3, grade::Side::below);
    probe::WorkloadQuestion named = two_passes();
    named.walls = probe::WallsScene{3, grade::Side::below};
    const probe::WorkloadQuestion sent = sent_as_data(named, scene);
    const grade::ProbeSession session =
        grade::ask_probe(RAYSTEP_REFERENCE_PROBE,
                         {{"bvh_workload", args(named)},
                          {"bvh_workload", args(sent)},
                          {"grid_workload", args(named)},
                          {"bvh_workload", {{"walls", {{"layers", 3}, {"side", 7}}}}}},
                         grade::ProbeRunLimits{});
    REQUIRE(session.answers.size() == 4);
    CHECK(session.answers[0].kind == grade::ProbeAnswer::Kind::result);
    CHECK(session.answers[0].value == session.answers[1].value);
    CHECK(session.answers[0].value == probe::timed_walk(Bvh(scene.primitives, BvhSplit::sah),
                                                        scene.rays, grade::shadow_rays(scene),
                                                        named.jitter, 2));
    CHECK(session.answers[2].value == probe::timed_walk(UniformGrid(scene.primitives), scene.rays,
                                                        grade::shadow_rays(scene), named.jitter,
                                                        2));
    // A side that is none of the three is refused, not taken as one
    CHECK(session.answers[3].kind != grade::ProbeAnswer::Kind::result);
}

TEST_CASE("the speed scene the probe makes itself is walked as the same scene sent as data") {
    const grade::WorkScene scene = grade::speed_scene(300);
    // 3,300 triangles, 60 spheres and 3 planes, whatever the number of rays; a shorter list of
    // rays is the longer one's start, as the speed check's brute force takes it
    CHECK(scene.primitives.triangles.size() == 3300);
    CHECK(scene.primitives.spheres.size() == 60);
    CHECK(scene.primitives.planes.size() == 3);
    const grade::WorkScene fewer = grade::speed_scene(100);
    REQUIRE(fewer.rays.size() == 100);
    CHECK(fewer.rays.back().origin == scene.rays[99].origin);
    CHECK(fewer.rays.back().direction == scene.rays[99].direction);

    probe::WorkloadQuestion named = two_passes();
    named.speed = probe::SpeedScene{300};
    const probe::WorkloadQuestion sent = sent_as_data(named, scene);
    const grade::ProbeSession session =
        grade::ask_probe(RAYSTEP_REFERENCE_PROBE,
                         {{"bvh_workload", args(named)},
                          {"bvh_workload", args(sent)},
                          {"grid_workload", args(named)},
                          {"grid_workload", args(sent)},
                          {"bvh_workload", {{"speed", {{"rays", -1}}}}}},
                         grade::ProbeRunLimits{});
    REQUIRE(session.answers.size() == 5);
    CHECK(session.answers[0].kind == grade::ProbeAnswer::Kind::result);
    CHECK(session.answers[0].value == session.answers[1].value);
    CHECK(session.answers[2].value == session.answers[3].value);
    CHECK(session.answers[0].value == probe::timed_walk(Bvh(scene.primitives, BvhSplit::sah),
                                                        scene.rays, grade::shadow_rays(scene),
                                                        named.jitter, 2));
    // A count of rays below zero is refused, not taken as none
    CHECK(session.answers[4].kind != grade::ProbeAnswer::Kind::result);
}

TEST_CASE("a timed walk's digest depends on its seed, and each grade draws a seed of its own") {
    // What a digest worked out for one seed beforehand is worth under another: nothing.
    const grade::WorkScene scene = grade::walls_scene(3, grade::Side::both);
    const std::vector<Ray> shadows = grade::shadow_rays(scene);
    const Bvh bvh(scene.primitives, BvhSplit::sah);
    const auto digest = [&](std::uint64_t seed) {
        return probe::timed_walk(bvh, scene.rays, shadows, probe::Jitter{seed, 1e-3, 1e-4}, 3);
    };
    CHECK(digest(1) == digest(1));
    CHECK(digest(1) != digest(2));
    // Sixteen grades' seeds, no two alike.
    std::set<std::uint64_t> seeds;
    for (int k = 0; k < 16; ++k)
        seeds.insert(grade::fresh_grade_seed());
    CHECK(seeds.size() == 16);
}
