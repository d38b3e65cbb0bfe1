// Stage 4's data judges (grading/4_accel/accel_judges.h), each built from the data a release's case
// file holds: what each takes and what it turns down.

#include <cmath>

#include "base/testing/catch.h"

#include "app/grade/data_judge.h"
#include "app/probe/tests/probe_answers.h"
#include "grading/4_accel/accel_judges.h"

namespace raystep {
namespace {

using grade::ProbeAnswer;
using probe::Json;

Json interval(double enter, double exit) {
    return {{"enter", probe::number(enter)}, {"exit", probe::number(exit)}};
}

// Each judge is read back from its data as the release reads it: dumped and parsed.
grade::Judge judge_from(const Json& data) {
    return grade::build_judge(Json::parse(data.dump()));
}

TEST_CASE("slab_interval: a ray that must hit passes only an interval within tolerance") {
    grade::SlabInterval exact;
    exact.must_hit = true;
    exact.enter = DoubleDouble(4);
    exact.exit = DoubleDouble(6);
    exact.enter_tolerance = DoubleDouble(1e-12);
    exact.exit_tolerance = DoubleDouble(1e-12);
    const grade::Judge judge = judge_from(grade::slab_interval_judge(exact));
    CHECK(judge(testing::result_answer(interval(4, 6))).passed);
    CHECK(judge(testing::result_answer(interval(4 + 1e-13, 6 - 1e-13))).passed);
    CHECK_FALSE(judge(testing::result_answer(interval(4, 6 + 1e-9))).passed);
    CHECK_FALSE(judge(testing::result_answer(interval(4 - 1e-9, 6))).passed);
    CHECK_FALSE(judge(testing::result_answer(interval(std::nan(""), 6))).passed);
    const grade::Verdict miss = judge(testing::result_answer(nullptr));
    CHECK_FALSE(miss.passed);
    CHECK(miss.got == "a miss");
    CHECK(miss.expected ==
          "t in [4, 6] (within 9.9999999999999998e-13 and 9.9999999999999998e-13)");
    const grade::Verdict reversed = judge(testing::result_answer(interval(6, 4)));
    CHECK_FALSE(reversed.passed);
    CHECK(reversed.got == "t in [6, 4], which is empty");
    ProbeAnswer threw;
    threw.kind = ProbeAnswer::Kind::threw;
    CHECK_FALSE(judge(threw).passed);
}

TEST_CASE("slab_interval: a ray that must miss passes only a miss; within rounding, either") {
    grade::SlabInterval miss;
    miss.must_miss = true;
    const grade::Judge must_miss = judge_from(grade::slab_interval_judge(miss));
    CHECK(must_miss(testing::result_answer(nullptr)).passed);
    const grade::Verdict hit = must_miss(testing::result_answer(interval(1, 2)));
    CHECK_FALSE(hit.passed);
    CHECK(hit.expected == "a miss");

    grade::SlabInterval touch;
    touch.enter = DoubleDouble(1);
    touch.exit = DoubleDouble(1);
    touch.enter_tolerance = DoubleDouble(1e-15);
    touch.exit_tolerance = DoubleDouble(1e-15);
    const grade::Judge either = judge_from(grade::slab_interval_judge(touch));
    CHECK(either(testing::result_answer(nullptr)).passed);
    CHECK(either(testing::result_answer(interval(1, 1))).passed);
    CHECK_FALSE(either(testing::result_answer(interval(1, 1.5))).passed);
    CHECK(either(testing::result_answer(interval(1, 1.5))).expected.find("or a miss") !=
          std::string::npos);
}

TEST_CASE("slab_interval: an infinite end must come out infinite, a finite end in double-double") {
    grade::SlabInterval open;
    open.must_hit = true;
    open.enter = DoubleDouble(0);
    open.exit = DoubleDouble(HUGE_VAL);
    open.enter_tolerance = DoubleDouble(1e-15);
    const grade::Judge judge = judge_from(grade::slab_interval_judge(open));
    CHECK(judge(testing::result_answer(interval(0, HUGE_VAL))).passed);
    CHECK_FALSE(judge(testing::result_answer(interval(0, 1e308))).passed);
    // 1 + 2^-60 within 2^-62: the double 1 is 2^-60 away, a judge by the rounded end would pass it
    grade::SlabInterval fine;
    fine.must_hit = true;
    fine.enter = two_sum(1, 0x1p-60);
    fine.exit = DoubleDouble(2);
    fine.enter_tolerance = DoubleDouble(0x1p-62);
    fine.exit_tolerance = DoubleDouble(0x1p-62);
    CHECK_FALSE(judge_from(grade::slab_interval_judge(fine))(testing::result_answer(interval(1, 2)))
                    .passed);
}

TEST_CASE("grid_cells: exactly the expected three integers") {
    const grade::Judge judge = judge_from(grade::grid_cells_judge({2, 3, 4}));
    CHECK(judge(testing::result_answer(Json::array({2, 3, 4}))).passed);
    const grade::Verdict off = judge(testing::result_answer(Json::array({2, 3, 5})));
    CHECK_FALSE(off.passed);
    CHECK(off.expected == "2 x 3 x 4");
    CHECK(off.got == "2 x 3 x 5");
    CHECK_FALSE(judge(testing::result_answer(Json::array({2.0, 3, 4}))).passed);
    CHECK_FALSE(judge(testing::result_answer(Json::array({2, 3}))).passed);
}

TEST_CASE("structure_hit: the same primitive at the same t, bit for bit, in a list of one") {
    const Hit hit{2.5, {0, 0, 1}, 0.25, 0.25};
    const PrimitiveHit expected{hit, PrimitiveKind::triangle, 3};
    const grade::Judge judge = judge_from(grade::structure_hit_judge(expected, 0.0));
    const auto one = [](const std::optional<PrimitiveHit>& h) {
        return testing::result_answer(Json::array({probe::primitive_hit(h)}));
    };
    CHECK(judge(one(expected)).passed);
    PrimitiveHit later = expected;
    later.hit.t = std::nextafter(2.5, 3.0);
    const grade::Verdict late = judge(one(later));
    CHECK_FALSE(late.passed);
    CHECK(late.expected == "triangle 3 at t = 2.5");
    CHECK(late.got == "triangle 3 at t = 2.5000000000000004");
    CHECK_FALSE(judge(one(PrimitiveHit{hit, PrimitiveKind::triangle, 4})).passed);
    CHECK_FALSE(judge(one(PrimitiveHit{hit, PrimitiveKind::sphere, 3})).passed);
    const grade::Verdict miss = judge(one(std::nullopt));
    CHECK_FALSE(miss.passed);
    CHECK(miss.got == "a miss");
    // The hit itself, or two answers, is not the answer to a list of one ray
    CHECK_FALSE(judge(testing::result_answer(probe::primitive_hit(expected))).passed);
    CHECK_FALSE(judge(testing::result_answer(Json::array(
                          {probe::primitive_hit(expected), probe::primitive_hit(expected)})))
                    .passed);

    const grade::Judge nothing = judge_from(grade::structure_hit_judge(std::nullopt, 0.0));
    CHECK(nothing(one(std::nullopt)).passed);
    CHECK_FALSE(nothing(one(expected)).passed);
}

TEST_CASE("structure_hit: with a tolerance, t within it on the same primitive; a NaN fails") {
    const PrimitiveHit expected{{1.0, {0, 0, 1}, 0.25, 0.25}, PrimitiveKind::sphere, 1};
    const grade::Judge judge = judge_from(grade::structure_hit_judge(expected, 1e-9));
    const auto at = [&](double t, std::size_t index) {
        PrimitiveHit got = expected;
        got.hit.t = t;
        got.index = index;
        return testing::result_answer(Json::array({probe::primitive_hit(got)}));
    };
    CHECK(judge(at(0.99999999999999978, 1)).passed);
    CHECK(judge(at(1.0 + 5e-10, 1)).passed);
    const grade::Verdict far = judge(at(1.0 + 2e-9, 1));
    CHECK_FALSE(far.passed);
    CHECK(far.expected == "sphere 1 at t = 1 (within 1.0000000000000001e-09)");
    CHECK_FALSE(judge(at(1.0, 0)).passed);
    CHECK_FALSE(judge(at(std::nan(""), 1)).passed);
}

TEST_CASE("structure_occluded: the expected boolean in a list of one") {
    const grade::Judge judge = judge_from(grade::structure_occluded_judge(true));
    CHECK(judge(testing::result_answer(Json::array({true}))).passed);
    const grade::Verdict wrong = judge(testing::result_answer(Json::array({false})));
    CHECK_FALSE(wrong.passed);
    CHECK(wrong.expected == "occluded");
    CHECK(wrong.got == "not occluded");
    CHECK(judge(testing::result_answer(Json::array({1}))).got == "not a boolean");
    CHECK_FALSE(judge(testing::result_answer(true)).passed);
    CHECK(judge_from(grade::structure_occluded_judge(false))(
              testing::result_answer(Json::array({false})))
              .passed);
}

}  // namespace
}  // namespace raystep
