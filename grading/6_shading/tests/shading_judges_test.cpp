// Stage 6's data judges: light samples and rays that leave a surface, each judged by what the
// contract promises and failed by an answer just outside it.

#include <cmath>
#include <limits>

#include "base/testing/catch.h"

#include "app/grade/data_judge.h"
#include "app/probe/tests/probe_answers.h"
#include "base/testing/special_values.h"
#include "grading/6_shading/shading_judges.h"

namespace raystep {
namespace {

using grade::build_judge;
using grade::ErrorBoundOrigin;
using grade::LeavingDirection;

using raystep::testing::kInf;
using raystep::testing::kNaN;

grade::ProbeAnswer sample(const Vec3& direction, double distance, const Vec3& intensity) {
    return testing::result_answer(probe::light_sample({direction, distance, intensity}));
}

TEST_CASE("light_sample: a distance or intensity just outside its tolerance fails, NaN too") {
    const grade::Judge judge = build_judge(
        grade::light_sample_judge({0.6, 0.8, 0}, 1e-15, DoubleDouble(5), DoubleDouble(1e-12),
                                  {1, 0.5, 0.25}, DoubleDoubleVec3(1e-12)));
    CHECK(judge(sample({0.6, 0.8, 0}, 5.0, {1, 0.5, 0.25})).passed);
    CHECK(judge(sample({0.6, 0.8, 0}, 5.0 + 0.9e-12, {1, 0.5, 0.25})).passed);
    CHECK_FALSE(judge(sample({0.6, 0.8, 0}, 5.0 + 1.1e-12, {1, 0.5, 0.25})).passed);
    CHECK_FALSE(judge(sample({0.6, 0.8, 0}, 5.0, {1, 0.5, 0.25 + 1.1e-12})).passed);
    CHECK_FALSE(judge(sample({0.6, 0.8 + 2e-15, 0}, 5.0, {1, 0.5, 0.25})).passed);
    CHECK_FALSE(judge(sample({0.6, 0.8, 0}, kNaN, {1, 0.5, 0.25})).passed);
    const grade::Verdict nan = judge(sample({0.6, 0.8, 0}, 5.0, {1, kNaN, 0.25}));
    CHECK_FALSE(nan.passed);
    CHECK(nan.expected ==
          "direction (0.59999999999999998, 0.80000000000000004, 0) (within 1.0000000000000001e-15)"
          ", distance 5 (within 9.9999999999999998e-13), intensity (1, 0.5, 0.25) (within "
          "(9.9999999999999998e-13, 9.9999999999999998e-13, 9.9999999999999998e-13))");
    CHECK(nan.got ==
          "light from (0.59999999999999998, 0.80000000000000004, 0) at 5, intensity "
          "(1, nan, 0.25)");
}

TEST_CASE("light_sample: an infinite distance is infinity itself, not the largest double") {
    const grade::Judge judge =
        build_judge(grade::light_sample_judge({0, 1, 0}, 1e-15, DoubleDouble(kInf), DoubleDouble(),
                                              DoubleDoubleVec3(1.0), DoubleDoubleVec3()));
    CHECK(judge(sample({0, 1, 0}, kInf, Vec3(1.0))).passed);
    CHECK_FALSE(judge(sample({0, 1, 0}, std::numeric_limits<double>::max(), Vec3(1.0))).passed);
}

// On the plane x = -1 facing -x, with d = 2^-49 (exactly a double's step there), 4 ulps of 4
// (the largest coordinate) beyond it at most.
const ErrorBoundOrigin kWall{{-1, 4, 2}, {-1, 0, 0}, DoubleDouble(0x1p-49), 4 * 0x1p-50};
const LeavingDirection kOut{{-0.8, 0, 0.6}, 8 * 0x1p-53, 3.0};

TEST_CASE("leaving_ray error_bound: an origin strictly beyond d, and within the ulps of it") {
    const grade::Judge judge = build_judge(grade::error_bound_judge(kWall, kOut));
    const double at_d = -1 - 0x1p-49;
    const double beyond = std::nextafter(at_d, -kInf);
    CHECK(judge(testing::ray_answer({{beyond, 4, 2}, kOut.direction, 0, 3})).passed);
    // At d exactly is not beyond it; the other side of the wall is the wrong side.
    CHECK_FALSE(judge(testing::ray_answer({{at_d, 4, 2}, kOut.direction, 0, 3})).passed);
    CHECK_FALSE(judge(testing::ray_answer({{-1 + 0x1p-48, 4, 2}, kOut.direction, 0, 3})).passed);
    // More than d + 4 ulps along n, or more than 4 ulps off the line.
    CHECK_FALSE(
        judge(testing::ray_answer({{-1 - 0x1p-49 - 0x1p-47 - 0x1p-50, 4, 2}, kOut.direction, 0, 3}))
            .passed);
    CHECK_FALSE(
        judge(testing::ray_answer({{beyond, 4 + 0x1p-47, 2}, kOut.direction, 0, 3})).passed);
    CHECK_FALSE(judge(testing::ray_answer({{beyond, kNaN, 2}, kOut.direction, 0, 3})).passed);
    // The t range is [0, distance], exactly, and the direction kept.
    CHECK_FALSE(judge(testing::ray_answer({{beyond, 4, 2}, kOut.direction, 1e-9, 3})).passed);
    CHECK_FALSE(judge(testing::ray_answer({{beyond, 4, 2}, kOut.direction, 0, kInf})).passed);
    CHECK_FALSE(judge(testing::ray_answer({{beyond, 4, 2}, {-0.8, 0, 0.6 + 1e-14}, 0, 3})).passed);
    const grade::Verdict wrong_side =
        judge(testing::ray_answer({{-0.5, 4, 2}, kOut.direction, 0, 3}));
    CHECK(wrong_side.expected ==
          "origin more than 1.7763568394002505e-15 and at most 5.3290705182007514e-15 along (-1, "
          "0, 0) from the point (-1, 4, 2), within 3.5527136788005009e-15 of that line, t in [0, "
          "3], direction (-0.80000000000000004, 0, 0.59999999999999998)");
}

TEST_CASE("leaving_ray along_normal: the origin within its tolerance per coordinate") {
    const grade::Judge judge =
        build_judge(grade::along_normal_judge({-1.125, 4, 2}, DoubleDoubleVec3(1e-15), kOut));
    CHECK(judge(testing::ray_answer({{-1.125, 4, 2}, kOut.direction, 0, 3})).passed);
    CHECK(judge(testing::ray_answer({{-1.125 + 0.9e-15, 4, 2}, kOut.direction, 0, 3})).passed);
    CHECK_FALSE(
        judge(testing::ray_answer({{-1.125 + 1.2e-15, 4, 2}, kOut.direction, 0, 3})).passed);
    CHECK_FALSE(judge(testing::ray_answer({{-0.875, 4, 2}, kOut.direction, 0, 3})).passed);
    CHECK_FALSE(judge(testing::ray_answer({{-1.125, 4, 2}, kOut.direction, 0.125, 3})).passed);
}

TEST_CASE("leaving_ray along_ray: the point itself, t from epsilon exactly") {
    const grade::Judge judge = build_judge(grade::along_ray_judge({-1, 4, 2}, 0.125, kOut));
    CHECK(judge(testing::ray_answer({{-1, 4, 2}, kOut.direction, 0.125, 3})).passed);
    CHECK_FALSE(
        judge(testing::ray_answer({{std::nextafter(-1.0, -2.0), 4, 2}, kOut.direction, 0.125, 3}))
            .passed);
    CHECK_FALSE(judge(testing::ray_answer({{-1, 4, 2}, kOut.direction, 0, 3})).passed);
    const grade::Verdict stub = judge(grade::ProbeAnswer{});
    CHECK_FALSE(stub.passed);
    CHECK(stub.got.empty());
}

TEST_CASE("leaving_ray: a judge with an unknown rule or a missing region throws") {
    probe::Json unknown = grade::along_ray_judge({0, 0, 0}, 0.1, kOut);
    unknown["rule"] = "along_tangent";
    CHECK_THROWS_AS(build_judge(unknown), std::invalid_argument);
    probe::Json no_region = grade::error_bound_judge(kWall, kOut);
    no_region.erase("region");
    CHECK_THROWS(build_judge(no_region));
    probe::Json bad_offset = grade::error_bound_judge(kWall, kOut);
    bad_offset["region"]["offset"] = 1e-15;
    CHECK_THROWS_AS(build_judge(bad_offset), std::invalid_argument);
}

}  // namespace
}  // namespace raystep
