// The typed calls (app/probe/probe_call.h): a query is the JSON the protocol has always carried
// (grader/probe/README.md), the probe's table answers it with this build's stage code, and a
// question of the wrong shape is refused as a thrown error, never read as something else.

#include "base/testing/catch.h"

#include <cmath>

#include "app/probe/call_reply.h"
#include "app/probe/render_calls.h"
#include "grading/1_vectors/vector_calls.h"
#include "grading/2_rays/ray_calls.h"
#include "grading/3_intersect/intersect_calls.h"
#include "grading/4_accel/accel_calls.h"
#include "grading/5_transforms/transform_calls.h"
#include "grading/6_shading/shading_calls.h"
#include "grading/7_recursion/recursion_calls.h"
#include "grading/8_sampling/sampling_calls.h"
#include "grading/9_refraction/refraction_calls.h"

namespace raystep {
namespace {

using probe::Json;

grade::ProbeAnswer answered(const grade::ProbeQuery& query) {
    static const probe::CallTable table = probe::stage_calls();
    return probe::answer_in_process(table, query);
}

TEST_CASE(
    "probe call: a function's question is its arguments in order, and its answer its result") {
    const grade::ProbeQuery query = probe::query(probe::dot_call, {{1, 2, 3}, {4, -5, 6}});
    CHECK(query.call == "dot");
    CHECK(query.args == Json::parse("[[1.0,2.0,3.0],[4.0,-5.0,6.0]]"));
    const grade::ProbeAnswer answer = answered(query);
    REQUIRE(answer.kind == grade::ProbeAnswer::Kind::result);
    CHECK(answer.value == Json(12.0));
}

TEST_CASE("probe call: non-finite numbers cross as the protocol's strings, both ways") {
    const grade::ProbeQuery query =
        probe::query(probe::normalize_call, {{HUGE_VAL, 0, std::nan("")}});
    CHECK(query.args == Json::parse(R"([["inf",0.0,"nan"]])"));
    const grade::ProbeAnswer answer = answered(query);
    REQUIRE(answer.kind == grade::ProbeAnswer::Kind::threw);
    CHECK(answer.exception_type == "domain_error");
}

TEST_CASE("probe call: a struct's question is an object of its named fields") {
    const Ray ray{{1, 2, 3}, {0, 0, -1}, 0.0, 10.0};
    const grade::ProbeQuery query = probe::query(probe::ray_at_call, {ray, 2.5});
    CHECK(query.call == "ray_at");
    CHECK(query.args.at("ray") == probe::ray(ray));
    CHECK(query.args.at("t") == Json(2.5));
    const grade::ProbeAnswer answer = answered(query);
    REQUIRE(answer.kind == grade::ProbeAnswer::Kind::result);
    CHECK(probe::vec3_from(answer.value) == Vec3(1, 2, 0.5));
}

TEST_CASE("probe call: the answer of a struct is an object, a list an array") {
    probe::RadianceQuestion question;
    question.ray = {{0, 1, 0}, {1, -1, 0}, 0.0, HUGE_VAL};
    question.bounces = 2;
    question.offset = {OffsetRule::along_ray, 1e-4};
    const grade::ProbeAnswer answer = answered(probe::query(probe::radiance_call, question));
    REQUIRE(answer.kind == grade::ProbeAnswer::Kind::result);
    CHECK(answer.value.at("colour") == probe::vec3({0, 0, 0}));
    REQUIRE(answer.value.at("rays").size() == 1);  // the eye ray, which the empty script misses
    CHECK(probe::ray_from(answer.value.at("rays")[0]).direction == question.ray.direction);
}

TEST_CASE("probe call: the ops of compose are the whole question, not one argument") {
    const TransformOp op{TransformOp::Kind::translate, {1, 2, 3}, 0.0};
    const grade::ProbeQuery query = probe::query(probe::compose_call, {op});
    CHECK(query.args == Json::array({probe::transform_op(op)}));
    const grade::ProbeAnswer answer = answered(query);
    REQUIRE(answer.kind == grade::ProbeAnswer::Kind::result);
    CHECK(probe::transform_from(answer.value).matrix[3] == glm::dvec4(1, 2, 3, 1));
}

TEST_CASE("probe call: a structure answers each ray with its hit, or with whether it is blocked") {
    PrimitiveList primitives;
    primitives.spheres.push_back({{0, 0, -5}, 1});
    probe::StructureQuestion question{
        primitives,
        {{{0, 0, 0}, {0, 0, -1}, 0.0, HUGE_VAL}, {{0, 0, 0}, {0, 1, 0}, 0.0, HUGE_VAL}},
        "sah",
        std::nullopt};
    const grade::ProbeAnswer hits = answered(probe::query(probe::bvh_call, question));
    REQUIRE(hits.kind == grade::ProbeAnswer::Kind::result);
    REQUIRE(hits.value.size() == 2);
    CHECK(probe::primitive_hit_from(hits.value[0])->hit.t == 4.0);
    CHECK(hits.value[1].is_null());
    question.occluded = true;
    CHECK(answered(probe::query(probe::bvh_call, question)).value == Json::array({true, false}));
    question.split.reset();  // a BVH's split must be named; a grid has none
    CHECK(answered(probe::query(probe::bvh_call, question)).kind ==
          grade::ProbeAnswer::Kind::threw);
    CHECK(answered(probe::query(probe::grid_call, question)).value == Json::array({true, false}));
}

TEST_CASE("probe call: an optional field is left out where it holds nothing, and read as absent") {
    probe::RenderQuestion question{"scenes/a.test", "depth",      64,          std::nullopt, 0.5,
                                   std::nullopt,    std::nullopt, std::nullopt};
    const grade::ProbeQuery query = probe::query(probe::render_call, question);
    CHECK(query.args == Json{{"scene", "scenes/a.test"},
                             {"view", "depth"},
                             {"max_width", 64},
                             {"camera_t_min", 0.5}});
    const probe::RenderQuestion read = probe::JsonCodec<probe::RenderQuestion>::read(query.args);
    CHECK_FALSE(read.seed.has_value());
    CHECK(read.camera_t_min == 0.5);
    CHECK_FALSE(read.camera_t_max.has_value());
    question.seed = 7;
    CHECK(probe::query(probe::render_call, question).args.at("seed") == Json(std::uint64_t(7)));
    question.lookfrom = Vec3(1.5, -2.0, 0.25);
    const probe::RenderQuestion moved = probe::JsonCodec<probe::RenderQuestion>::read(
        probe::query(probe::render_call, question).args);
    CHECK(moved.lookfrom == Vec3(1.5, -2.0, 0.25));
}

TEST_CASE("probe call: a question of the wrong shape is refused, not read another way") {
    // One vector short, one too many, a number for a vector, a negative seed, a missing field,
    // a fractional pixel index: each a thrown error that names no result.
    const std::vector<grade::ProbeQuery> wrong = {
        {"dot", Json::parse("[[1.0,2.0,3.0]]")},
        {"dot", Json::parse("[[1.0,2.0,3.0],[1.0,2.0,3.0],[1.0,2.0,3.0]]")},
        {"length", Json::parse("[4.0]")},
        {"render", Json{{"scene", "x.test"}, {"view", "depth"}, {"max_width", 4}, {"seed", -1}}},
        {"ray_at", Json{{"t", 1.0}}},
        {"perspective_rays", Json{{"lookfrom", probe::vec3({0, 0, 0})},
                                  {"lookat", probe::vec3({0, 0, -1})},
                                  {"up", probe::vec3({0, 1, 0})},
                                  {"fovy", 45.0},
                                  {"width", 4},
                                  {"height", 4},
                                  {"pixels", Json::parse("[[0.5,1]]")}}},
    };
    for (const grade::ProbeQuery& query : wrong) {
        INFO(query.call << " " << query.args.dump());
        CHECK(answered(query).kind == grade::ProbeAnswer::Kind::threw);
    }
}

TEST_CASE("probe call: a random call answers each stream, the same stream alike") {
    const grade::ProbeQuery query = probe::query(probe::jittered_samples_call, {2, 8, {5, 5, 6}});
    CHECK(query.args == Json::parse(R"({"strata": 2, "seed": 8, "streams": [5, 5, 6]})"));
    const grade::ProbeAnswer answer = answered(query);
    REQUIRE(answer.kind == grade::ProbeAnswer::Kind::result);
    const probe::StreamPoints points =
        probe::read_answer(probe::jittered_samples_call, answer.value);
    REQUIRE(points.size() == 3);
    CHECK(points[0].size() == 4);
    CHECK(points[0] == points[1]);
    CHECK(points[0] != points[2]);
}

TEST_CASE("probe call: a film radiance is its kind's function, and names a field it lacks") {
    probe::FilmRadianceModel ramp;
    ramp.kind = "ramp";
    ramp.value = 0.5;
    ramp.gradient = Vec2(0.25, -1.0);
    CHECK(probe::film_radiance(ramp)({2, 1}) == Color(0.0));
    probe::FilmRadianceModel edge;
    edge.kind = "edge";
    edge.through = Vec2(1, 1);
    edge.normal = Vec2(0, 1);
    edge.bright = 0.75;
    edge.dark = 0.25;
    CHECK(probe::film_radiance(edge)({0, 1}) == Color(0.75));
    CHECK(probe::film_radiance(edge)({0, 0.5}) == Color(0.25));
    edge.dark.reset();
    CHECK_THROWS_WITH(probe::film_radiance(edge), "the film radiance \"edge\" needs \"dark\"");
    probe::FilmRadianceModel unknown;
    unknown.kind = "noise";
    CHECK_THROWS_WITH(probe::film_radiance(unknown), "unknown film radiance \"noise\"");
}

TEST_CASE("probe call: a blocker blocks a ray that crosses it within its t range only") {
    const std::vector<probe::Parallelogram> blockers = {{{-1, 1, -1}, {2, 0, 0}, {0, 0, 2}}};
    const Ray up{{0, 0, 0}, {0, 1, 0}, 0.0, 2.0};
    CHECK(probe::crosses_any(blockers, up));
    CHECK_FALSE(probe::crosses_any(blockers, Ray{{0, 0, 0}, {0, 1, 0}, 0.0, 0.5}));
    CHECK_FALSE(probe::crosses_any(blockers, Ray{{3, 0, 0}, {0, 1, 0}, 0.0, 2.0}));
    CHECK_FALSE(probe::crosses_any({}, up));
}

TEST_CASE("probe call: every typed call is in the probe's table once, by its own name") {
    const probe::CallTable table = probe::stage_calls();
    std::vector<std::string> names;
    const auto collect = [&](const auto& calls) {
        std::apply([&](const auto&... call) { (names.push_back(call.name), ...); }, calls);
    };
    collect(probe::vector_calls);
    collect(probe::ray_calls);
    collect(probe::intersect_calls);
    collect(probe::accel_calls);
    collect(probe::transform_calls);
    collect(probe::shading_calls);
    collect(probe::recursion_calls);
    collect(probe::sampling_calls);
    collect(probe::refraction_calls);
    names.push_back(probe::render_call.name);
    // Stages 1 to 9 (8 + 3 + 2 + 4 + 8 + 7 + 2 + 10 + 7), and render
    CHECK(names.size() == 52);
    for (const std::string& name : names) {
        INFO(name);
        CHECK(table.count(name) == 1);
        CHECK(std::count(names.begin(), names.end(), name) == 1);
    }
}

}  // namespace
}  // namespace raystep
