// Stage 10's data judges (grading/10_path_tracing/path_tracing_judges.h) on answers made by hand:
// any orthonormal frame about the normal and nothing else, the roulette's stop and its weight,
// and a light sample judged by its density and radiance alone where the point is on the light's
// plane.

#include <cmath>

#include <glm/geometric.hpp>

#include "base/testing/catch.h"

#include "app/grade/data_judge.h"
#include "app/probe/tests/probe_answers.h"
#include "base/testing/special_values.h"
#include "grading/10_path_tracing/path_tracing_json.h"
#include "grading/10_path_tracing/path_tracing_judges.h"

namespace raystep::grade {
namespace {

using raystep::testing::kNaN;

ProbeAnswer frame_answer(const Frame& f) {
    return testing::result_answer(probe::JsonCodec<Frame>::write(f));
}

ProbeAnswer roulette_answer(const std::optional<Color>& weight) {
    return testing::result_answer(probe::JsonCodec<std::optional<Color>>::write(weight));
}

ProbeAnswer light_answer(const LightDirectionSample& s) {
    return testing::result_answer(probe::JsonCodec<LightDirectionSample>::write(s));
}

TEST_CASE("frame_around judge: takes any orthonormal frame about the normal, either handedness") {
    const Vec3 n = glm::normalize(Vec3{1, 2, 2});
    const Judge judge = build_judge(frame_around_judge(n, 1e-12));
    const Vec3 u = glm::normalize(glm::cross(Vec3{1, 0, 0}, n));
    const Vec3 v = glm::cross(n, u);
    CHECK(judge(frame_answer({u, v, n})).passed);
    CHECK(judge(frame_answer({v, u, n})).passed);
    const double c = std::cos(1.0);
    const double s = std::sin(1.0);
    CHECK(judge(frame_answer({c * u + s * v, -s * u + c * v, n})).passed);
}

TEST_CASE("frame_around judge: refuses a frame about another axis, unnormalized or skewed") {
    const Vec3 n{0, 0, 1};
    const Judge judge = build_judge(frame_around_judge(n, 1e-12));
    CHECK_FALSE(judge(frame_answer({{0, 1, 0}, {0, 0, 1}, {1, 0, 0}})).passed);
    CHECK_FALSE(judge(frame_answer({{2, 0, 0}, {0, 1, 0}, n})).passed);
    CHECK_FALSE(judge(frame_answer({glm::normalize(Vec3{1, 0.1, 0}), {0, 1, 0}, n})).passed);
    CHECK_FALSE(judge(frame_answer({{kNaN, 0, 0}, {0, 1, 0}, n})).passed);
}

TEST_CASE("roulette judge: nullopt where the path stops, the weight within tolerance elsewhere") {
    const Judge stops = build_judge(roulette_judge(std::nullopt, 1e-12));
    CHECK(stops(roulette_answer(std::nullopt)).passed);
    CHECK_FALSE(stops(roulette_answer(Color(0.5))).passed);
    const Judge goes_on = build_judge(roulette_judge(Color(1, 0.5, 0.2), 1e-12));
    CHECK(goes_on(roulette_answer(Color(1, 0.5, 0.2))).passed);
    CHECK_FALSE(goes_on(roulette_answer(Color(0.5, 0.25, 0.1))).passed);
    CHECK_FALSE(goes_on(roulette_answer(std::nullopt)).passed);
    CHECK_FALSE(goes_on(roulette_answer(Color(kNaN))).passed);
}

TEST_CASE(
    "light_direction_sample judge: every field, or the density and radiance alone where "
    "the density is 0") {
    const LightDirectionSample expected{{0, 0, 1}, 2, 4, {1, 2, 3}};
    const Judge judge = build_judge(light_direction_sample_judge(expected, 1e-12, 1e-10));
    CHECK(judge(light_answer(expected)).passed);
    CHECK_FALSE(judge(light_answer({{0, 0, 1}, 2, 4 * (1 + 1e-8), {1, 2, 3}})).passed);
    CHECK_FALSE(judge(light_answer({{0, 0, 1}, 2.5, 4, {1, 2, 3}})).passed);
    CHECK_FALSE(judge(light_answer({{0, 1, 0}, 2, 4, {1, 2, 3}})).passed);
    CHECK_FALSE(judge(light_answer({{0, 0, 1}, 2, 4, {0, 0, 0}})).passed);

    const LightDirectionSample on_plane{{1, 0, 0}, 3, 0, {0, 0, 0}};
    const Judge edge_on = build_judge(light_direction_sample_judge(on_plane, 1e-12, 1e-10));
    CHECK(edge_on(light_answer({{0, 0, 0}, 0, 0, {0, 0, 0}})).passed);
    CHECK_FALSE(edge_on(light_answer({{1, 0, 0}, 3, 1e300, {0, 0, 0}})).passed);
    CHECK_FALSE(edge_on(light_answer({{1, 0, 0}, 3, 0, {1, 1, 1}})).passed);
}

}  // namespace
}  // namespace raystep::grade
