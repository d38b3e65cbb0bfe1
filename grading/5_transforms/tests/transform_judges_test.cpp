// Stage 5's data judges (grading/5_transforms/transform_judges.h) on answers made by hand: each
// fails the answer a wrong transform gives by the smallest margin there is, a NaN, and a stand-in
// for what must not be finite, and each rejects ill-formed data rather than judge by it.

#include <cmath>
#include <limits>

#include "base/testing/catch.h"

#include "app/grade/data_judge.h"
#include "app/probe/tests/probe_answers.h"
#include "app/protocol/wide_json.h"
#include "base/testing/special_values.h"
#include "grading/5_transforms/transform_judges.h"

namespace raystep::grade {
namespace {

using raystep::testing::kInf;

ProbeAnswer transform_answer(const Mat4& matrix, const Mat4& inverse) {
    return testing::result_answer(probe::transform({matrix, inverse}));
}

ProbeAnswer hit_answer(double t, const Vec3& normal) {
    Hit hit;
    hit.t = t;
    hit.normal = normal;
    return testing::result_answer(probe::hit(hit));
}

double next_up(double x) {
    return std::nextafter(x, kInf);
}

// T(1, 2, 3) and its inverse, every entry exact.
Mat4 translation() {
    Mat4 m(1.0);
    m[3] = Vec4(1, 2, 3, 1);
    return m;
}

Mat4 inverse_translation() {
    Mat4 m(1.0);
    m[3] = Vec4(-1, -2, -3, 1);
    return m;
}

TEST_CASE("a matrix judge with zero tolerance fails an entry one ulp off, and a NaN") {
    const Judge judge =
        build_judge(near_wide_matrix_judge(DoubleDoubleMat4(translation()), DoubleDoubleMat4()));
    CHECK(judge(testing::result_answer(probe::mat4(translation()))).passed);
    Mat4 off = translation();
    off[3][1] = next_up(2.0);
    const Verdict one_ulp = judge(testing::result_answer(probe::mat4(off)));
    CHECK_FALSE(one_ulp.passed);
    CHECK(one_ulp.expected == "matrix row 1 column 3 2 (within 0)");
    CHECK(one_ulp.got.rfind("matrix row 1 column 3 2.0000000000000004; matrix rows [", 0) == 0);
    Mat4 nan = translation();
    nan[0][0] = std::nan("");
    CHECK_FALSE(judge(testing::result_answer(probe::mat4(nan))).passed);
    ProbeAnswer threw;
    threw.kind = ProbeAnswer::Kind::threw;
    CHECK_FALSE(judge(threw).passed);
}

TEST_CASE("a matrix judge compares in double-double, the bits below a double's included") {
    // An entry of 1 + 2^-60 within 2^-62: the double 1 is 2^-60 away, and a judge by the
    // expectation rounded to double would pass it.
    DoubleDoubleMat4 expected(Mat4(1.0));
    expected[0][0] = two_sum(1, 0x1p-60);
    DoubleDoubleMat4 tolerance;
    tolerance[0][0] = DoubleDouble(0x1p-62);
    CHECK_FALSE(build_judge(near_wide_matrix_judge(expected, tolerance))(
                    testing::result_answer(probe::mat4(Mat4(1.0))))
                    .passed);
    tolerance[0][0] = DoubleDouble(0x1p-59);
    CHECK(build_judge(near_wide_matrix_judge(expected, tolerance))(
              testing::result_answer(probe::mat4(Mat4(1.0))))
              .passed);
}

TEST_CASE("a transform judge judges the matrix, then the inverse") {
    const Judge judge = build_judge(
        near_wide_transform_judge(DoubleDoubleMat4(translation()), DoubleDoubleMat4(),
                                  DoubleDoubleMat4(inverse_translation()), DoubleDoubleMat4()));
    CHECK(judge(transform_answer(translation(), inverse_translation())).passed);
    Mat4 inverse_off = inverse_translation();
    inverse_off[3][2] = std::nextafter(-3.0, 0.0);
    const Verdict inverse = judge(transform_answer(translation(), inverse_off));
    CHECK_FALSE(inverse.passed);
    CHECK(inverse.expected == "inverse row 2 column 3 -3 (within 0)");
    // Both wrong: the matrix is named first.
    const Verdict both = judge(transform_answer(inverse_translation(), inverse_off));
    CHECK_FALSE(both.passed);
    CHECK(both.expected.rfind("matrix row 0 column 3 1", 0) == 0);
    // The inverse given as the matrix itself: a transform that maps back the wrong way.
    CHECK_FALSE(judge(transform_answer(translation(), translation())).passed);
}

TEST_CASE("a singular scale's inverse must not hold a finite stand-in for 1 / 0") {
    Mat4 scale(1.0);
    scale[0][0] = 2.0;
    scale[1][1] = 0.0;
    scale[2][2] = 0.5;
    const Judge judge = build_judge(singular_transform_judge(scale, {0.5, std::nullopt, 2.0}));
    Mat4 inverse(1.0);
    inverse[0][0] = 0.5;
    inverse[1][1] = kInf;
    inverse[2][2] = 2.0;
    CHECK(judge(transform_answer(scale, inverse)).passed);
    Mat4 nan_inverse = inverse;
    nan_inverse[1][1] = std::nan("");
    CHECK(judge(transform_answer(scale, nan_inverse)).passed);
    Mat4 stand_in = inverse;
    stand_in[1][1] = std::numeric_limits<double>::max();
    const Verdict finite = judge(transform_answer(scale, stand_in));
    CHECK_FALSE(finite.passed);
    CHECK(finite.expected ==
          "matrix rows [2, 0, 0, 0]; [0, 0, 0, 0]; [0, 0, 0.5, 0]; [0, 0, 0, 1], inverse diagonal "
          "0.5, not finite (1 / 0), 2");
    CHECK(finite.got.rfind("inverse rows [0.5, 0, 0, 0]; [0, 1.7976931348623157e+308", 0) == 0);
    Mat4 zero_stand_in = inverse;
    zero_stand_in[1][1] = 0.0;
    CHECK_FALSE(judge(transform_answer(scale, zero_stand_in)).passed);
    Mat4 reciprocal_off = inverse;
    reciprocal_off[2][2] = next_up(2.0);
    CHECK_FALSE(judge(transform_answer(scale, reciprocal_off)).passed);
    Mat4 matrix_off = scale;
    matrix_off[0][0] = next_up(2.0);
    CHECK_FALSE(judge(transform_answer(matrix_off, inverse)).passed);
}

TEST_CASE("a ray judge holds origin and direction to their tolerances and t to the exact bounds") {
    const DoubleDoubleVec3 tolerance(1e-15);
    const Judge judge =
        build_judge(near_wide_ray_judge({1, 1, 2}, tolerance, {0, 2, 2}, tolerance, 0.25, kInf));
    CHECK(judge(testing::result_answer(probe::ray({{1, 1, 2}, {0, 2, 2}, 0.25, kInf}))).passed);
    // The direction normalized: the object-frame ray must keep M^-1 D's length.
    const Verdict normalized = judge(testing::result_answer(
        probe::ray({{1, 1, 2}, {0, std::sqrt(0.5), std::sqrt(0.5)}, 0.25, kInf})));
    CHECK_FALSE(normalized.passed);
    CHECK(normalized.expected ==
          "origin (1, 1, 2), direction (0, 2, 2), t in [0.25, inf] (within "
          "(1.0000000000000001e-15, 1.0000000000000001e-15, "
          "1.0000000000000001e-15) and (1.0000000000000001e-15, "
          "1.0000000000000001e-15, 1.0000000000000001e-15))");
    CHECK_FALSE(
        judge(testing::result_answer(probe::ray({{1, 1, 2}, {0, 2, 2}, next_up(0.25), kInf})))
            .passed);
    CHECK_FALSE(
        judge(testing::result_answer(probe::ray({{1, 1, 2}, {0, 2, 2}, 0.25, 1e300}))).passed);
    CHECK_FALSE(
        judge(testing::result_answer(probe::ray({{1, 1, 2.01}, {0, 2, 2}, 0.25, kInf}))).passed);
    CHECK_FALSE(
        judge(testing::result_answer(probe::ray({{std::nan(""), 1, 2}, {0, 2, 2}, 0.25, kInf})))
            .passed);
}

TEST_CASE("a hit judge fails a hit where a miss is due, a miss where a hit is, and a bad hit") {
    const Judge miss = build_judge(wide_miss_judge());
    CHECK(miss(testing::result_answer(probe::hit(std::nullopt))).passed);
    const Verdict false_hit = miss(hit_answer(8, {0, 1, 0}));
    CHECK_FALSE(false_hit.passed);
    CHECK(false_hit.expected == "a miss");
    CHECK(false_hit.got == "t = 8, normal (0, 1, 0)");

    const Judge hit =
        build_judge(near_wide_hit_judge(8, 1e-14, {0, 1, 0}, DoubleDoubleVec3(1e-15)));
    CHECK(hit(hit_answer(8, {0, 1, 0})).passed);
    const Verdict false_miss = hit(testing::result_answer(probe::hit(std::nullopt)));
    CHECK_FALSE(false_miss.passed);
    CHECK(false_miss.expected ==
          "t = 8 (within 1e-14), unit normal (0, 1, 0) (within (1.0000000000000001e-15, "
          "1.0000000000000001e-15, 1.0000000000000001e-15))");
    CHECK(false_miss.got == "a miss");
    // t in the object frame's units: half the world distance, as a normalized object ray gives.
    CHECK_FALSE(hit(hit_answer(4, {0, 1, 0})).passed);
    CHECK_FALSE(hit(hit_answer(std::nan(""), {0, 1, 0})).passed);
    // The normal not normalized, and the normal the wrong way.
    CHECK_FALSE(hit(hit_answer(8, {0, 2, 0})).passed);
    CHECK_FALSE(hit(hit_answer(8, {0, -1, 0})).passed);
    // Within its tolerance but not of unit length: the judge by tolerance alone would pass it.
    const Judge loose =
        build_judge(near_wide_hit_judge(8, 1e-14, {0, 1, 0}, DoubleDoubleVec3(0.1)));
    CHECK(loose(hit_answer(8, {0, 1, 0})).passed);
    CHECK_FALSE(loose(hit_answer(8, {0, 1.05, 0})).passed);
}

TEST_CASE("a transform judge's ill-formed data throws rather than judge") {
    const DoubleDoubleMat4 identity(Mat4(1.0));
    probe::Json matrix = near_wide_matrix_judge(identity, DoubleDoubleMat4());
    matrix["tolerance"].erase(15);
    CHECK_THROWS(build_judge(matrix));
    probe::Json transform =
        near_wide_transform_judge(identity, DoubleDoubleMat4(), identity, DoubleDoubleMat4());
    transform.erase("inverse_tolerance");
    CHECK_THROWS(build_judge(transform));
    probe::Json singular = singular_transform_judge(Mat4(1.0), {1.0, std::nullopt, 1.0});
    singular["inverse_diagonal"][1] = "infinite";
    CHECK_THROWS(build_judge(singular));
    singular["inverse_diagonal"] = probe::Json::array({1.0, 1.0});
    CHECK_THROWS(build_judge(singular));
    probe::Json ray =
        near_wide_ray_judge({0, 0, 0}, DoubleDoubleVec3(), {1, 0, 0}, DoubleDoubleVec3(), 0, 1);
    ray["origin"][0] = 0.5;
    CHECK_THROWS(build_judge(ray));
    probe::Json hit = near_wide_hit_judge(1, 0, {1, 0, 0}, DoubleDoubleVec3());
    hit.erase("t");
    CHECK_THROWS(build_judge(hit));
    hit = wide_miss_judge();
    hit["hit"] = "no";
    CHECK_THROWS(build_judge(hit));
}

}  // namespace
}  // namespace raystep::grade
