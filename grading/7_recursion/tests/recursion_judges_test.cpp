// Stage 7's data judges: the mirror ray, its unbounded end, and radiance's colour and every ray it
// asked about, each failed by an answer just outside what the contract promises.

#include <cmath>
#include <limits>
#include <vector>

#include "base/testing/catch.h"

#include "app/grade/data_judge.h"
#include "app/probe/tests/probe_answers.h"
#include "base/testing/special_values.h"
#include "grading/7_recursion/recursion_judges.h"

namespace raystep {
namespace {

using grade::build_judge;
using grade::ExpectedRay;

using raystep::testing::kInf;
using raystep::testing::kNaN;
const double kMax = std::numeric_limits<double>::max();

grade::ProbeAnswer radiance(const Vec3& colour, const std::vector<Ray>& rays) {
    probe::Json list = probe::Json::array();
    for (const Ray& r : rays)
        list.push_back(probe::ray(r));
    return testing::result_answer({{"colour", probe::vec3(colour)}, {"rays", list}});
}

// From (1, 0, 0) on the floor y = 0 towards (1, 1, 0) / sqrt 2, along_normal's origin 1e-4 up.
const Vec3 kUpRight{std::sqrt(0.5), std::sqrt(0.5), 0};
const DoubleDouble kHalfRoot = sqrt(DoubleDouble(0.5));
const DoubleDoubleVec3 kWideUp{kHalfRoot, kHalfRoot, DoubleDouble()};
const ExpectedRay kMirror{
    {1, 1e-4, 0}, DoubleDouble(1e-15), kWideUp, DoubleDouble(1e-15), 0.0, kInf, {}};
// The floor's error-bound origin: more than 2^-60 above (1, 0, 0), 2^-50 beyond that at most.
const ExpectedRay kBounded{
    {},
    DoubleDouble(),
    kWideUp,
    DoubleDouble(1e-15),
    0.0,
    kInf,
    grade::ErrorBoundOrigin{{1, 0, 0}, {0, 1, 0}, DoubleDouble(0x1p-60), 0x1p-50}};

TEST_CASE("mirror_ray: every coordinate within its tolerance, an unbounded end, NaN fails") {
    const grade::Judge judge = build_judge(grade::mirror_ray_judge(kMirror));
    CHECK(judge(testing::ray_answer({{1, 1e-4, 0}, kUpRight, 0, kInf})).passed);
    // The largest double admits the same hits as infinity: only unbounded_ray asks for infinity.
    CHECK(judge(testing::ray_answer({{1, 1e-4, 0}, kUpRight, 0, kMax})).passed);
    CHECK_FALSE(judge(testing::ray_answer({{1, 1e-4, 0}, kUpRight, 0, 1e300})).passed);
    CHECK_FALSE(judge(testing::ray_answer({{1, 1e-4 + 2e-15, 0}, kUpRight, 0, kInf})).passed);
    CHECK_FALSE(
        judge(testing::ray_answer({{1, 1e-4, 0}, {kUpRight.x, kUpRight.y + 2e-15, 0}, 0, kInf}))
            .passed);
    CHECK_FALSE(judge(testing::ray_answer({{1, 1e-4, 0}, {kUpRight.x, kNaN, 0}, 0, kInf})).passed);
    CHECK_FALSE(judge(testing::ray_answer({{1, 1e-4, 0}, kUpRight, 1e-4, kInf})).passed);
    const grade::Verdict off = judge(testing::ray_answer({{1, 1e-4, kNaN}, kUpRight, 0, kInf}));
    CHECK_FALSE(off.passed);
    CHECK(off.expected ==
          "origin (1, 0.0001, 0) (within 1.0000000000000001e-15), direction "
          "(0.70710678118654757, 0.70710678118654757, 0) (within "
          "1.0000000000000001e-15), t in [0, inf]");
}

TEST_CASE("mirror_ray: an error-bound origin strictly beyond d, never on the floor's far side") {
    const grade::Judge judge = build_judge(grade::mirror_ray_judge(kBounded));
    CHECK(judge(testing::ray_answer({{1, 0x1p-55, 0}, kUpRight, 0, kInf})).passed);
    CHECK_FALSE(judge(testing::ray_answer({{1, 0x1p-60, 0}, kUpRight, 0, kInf})).passed);
    CHECK_FALSE(judge(testing::ray_answer({{1, -0x1p-55, 0}, kUpRight, 0, kInf})).passed);
    CHECK_FALSE(judge(testing::ray_answer({{1, 0x1p-48, 0}, kUpRight, 0, kInf})).passed);
    CHECK(judge(testing::ray_answer({{1, -0x1p-55, 0}, kUpRight, 0, kInf}))
              .expected.rfind("origin more than ", 0) == 0);
}

TEST_CASE("unbounded_ray: infinity itself, and the largest double named as not it") {
    const grade::Judge judge = build_judge(grade::unbounded_ray_judge());
    CHECK(judge(testing::ray_answer({{1, 1e-4, 0}, kUpRight, 0, kInf})).passed);
    const grade::Verdict largest = judge(testing::ray_answer({{1, 1e-4, 0}, kUpRight, 0, kMax}));
    CHECK_FALSE(largest.passed);
    CHECK(largest.got.find("the header promises infinity") != std::string::npos);
    CHECK_FALSE(judge(testing::ray_answer({{1, 1e-4, 0}, kUpRight, 0, kNaN})).passed);
}

TEST_CASE("radiance: the colour within its tolerance and every ray asked, no more, no fewer") {
    const ExpectedRay eye{{0, 1, 0}, DoubleDouble(), {1, 0, 0}, DoubleDouble(), 0.0, kInf, {}};
    const grade::Judge judge =
        build_judge(grade::radiance_judge({0.5, 0.25, 1}, DoubleDoubleVec3(1e-12), {eye, kMirror}));
    const Ray eye_ray{{0, 1, 0}, {1, 0, 0}, 0, kInf};
    const Ray mirror_ray{{1, 1e-4, 0}, kUpRight, 0, kInf};
    CHECK(judge(radiance({0.5, 0.25, 1}, {eye_ray, mirror_ray})).passed);
    CHECK_FALSE(judge(radiance({0.5, 0.25 + 1.1e-12, 1}, {eye_ray, mirror_ray})).passed);
    CHECK_FALSE(judge(radiance({0.5, kNaN, 1}, {eye_ray, mirror_ray})).passed);
    CHECK_FALSE(judge(radiance({0.5, 0.25, 1}, {eye_ray})).passed);
    CHECK_FALSE(judge(radiance({0.5, 0.25, 1}, {eye_ray, mirror_ray, mirror_ray})).passed);
    // The eye ray is asked exactly as given: a moved eye is a wrong first ray.
    CHECK_FALSE(
        judge(radiance({0.5, 0.25, 1}, {{{0, 1, 1e-300}, {1, 0, 0}, 0, kInf}, mirror_ray})).passed);
    const grade::Verdict second =
        judge(radiance({0.5, 0.25, 1}, {eye_ray, {{1, 0, 0}, kUpRight, 0, kInf}}));
    CHECK_FALSE(second.passed);
    CHECK(second.expected.rfind("ray 1: origin (1, 0.0001, 0)", 0) == 0);
    CHECK(second.got.rfind("ray 1: origin (1, 0, 0)", 0) == 0);
    const grade::Verdict fewer = judge(radiance({0.5, 0.25, 1}, {eye_ray}));
    CHECK(fewer.expected ==
          "colour (0.5, 0.25, 1) (within (9.9999999999999998e-13, 9.9999999999999998e-13, "
          "9.9999999999999998e-13)) after asking about 2 ray(s)");
    CHECK(fewer.got == "colour (0.5, 0.25, 1) after asking about 1 ray(s)");
}

TEST_CASE("radiance: a judge whose rays are no list, or whose ray lacks its origin, throws") {
    probe::Json no_list = grade::radiance_judge(DoubleDoubleVec3(), DoubleDoubleVec3(), {kMirror});
    no_list["rays"] = probe::Json::object();
    CHECK_THROWS_AS(build_judge(no_list), std::invalid_argument);
    probe::Json no_origin =
        grade::radiance_judge(DoubleDoubleVec3(), DoubleDoubleVec3(), {kMirror});
    no_origin["rays"][0].erase("origin");
    CHECK_THROWS(build_judge(no_origin));
    probe::Json no_colour =
        grade::radiance_judge(DoubleDoubleVec3(), DoubleDoubleVec3(), {kMirror});
    no_colour.erase("colour");
    CHECK_THROWS(build_judge(no_colour));
}

}  // namespace
}  // namespace raystep
