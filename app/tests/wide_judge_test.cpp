// A long-double expectation written into a release's case file and read back: every bit kept, so
// that a release judges by the number the grader decided.

#include <cfloat>
#include <cmath>
#include <set>
#include <string>

#include <catch2/catch.hpp>

#include "app/grade/data_judge.h"
#include "app/grade/value_judges.h"
#include "app/protocol/wide_json.h"
#include "app/tests/probe_answers.h"

namespace raystep {
namespace {

TEST_CASE("every data judge this build registers has a name of its own") {
    // build_judge takes the first judge of a name: a second, from another file, would be
    // silently hidden, and a case file meant for it judged by the other.
    std::set<std::string> names;
    for (const grade::DataJudge& judge : grade::JudgeRegistry::entries()) {
        INFO(judge.name);
        CHECK(names.insert(judge.name).second);
    }
    CHECK(names.size() > 10);
}

TEST_CASE("a long double survives its [hi, lo] pair bit for bit") {
    const Wide third = 1.0L / 3.0L;
    const probe::Json written = probe::wide(third);
    CHECK(probe::wide_from(written) == third);
    CHECK(probe::wide_from(probe::Json::parse(written.dump())) == third);
    CHECK(std::isinf(probe::wide_from(probe::wide(static_cast<Wide>(HUGE_VAL)))));
    CHECK(std::isnan(probe::wide_from(probe::wide(static_cast<Wide>(std::nan(""))))));
    CHECK(std::signbit(probe::wide_from(probe::wide(-0.0L))));
    CHECK_THROWS_AS(probe::wide_from(probe::Json(0.5)), std::invalid_argument);
}

TEST_CASE("a wide judge compares in long double, the bits below a double's included") {
    if (LDBL_MANT_DIG < 64) {
        WARN("long double is a double here: nothing below a double to keep");
        return;
    }
    // 1 + 2^-60 within 2^-62: the double 1 is 2^-60 away, a judge by the rounded 1 would pass it.
    const Wide expected = 1.0L + 0x1p-60L;
    const grade::Judge number =
        grade::build_judge(grade::near_wide_number_judge(expected, 0x1p-62L));
    CHECK_FALSE(number(testing::result_answer(probe::number(1.0))).passed);
    CHECK(grade::build_judge(grade::near_wide_number_judge(expected, 0x1p-59L))(
              testing::result_answer(probe::number(1.0)))
              .passed);
}

TEST_CASE("a wide vector judge fails a NaN, a component out of tolerance and a non-unit normal") {
    const WideVec expected{0.6L, 0.8L, 0.0L};
    const WideVec tolerance{1e-15L, 1e-15L, 1e-15L};
    const grade::Judge unit =
        grade::build_judge(grade::near_wide_vec3_judge(expected, tolerance, true));
    CHECK(unit(testing::result_answer(probe::vec3({0.6, 0.8, 0.0}))).passed);
    CHECK_FALSE(unit(testing::result_answer(probe::vec3({0.6, 0.8, std::nan("")}))).passed);
    CHECK_FALSE(unit(testing::result_answer(probe::vec3({0.6, 0.81, 0.0}))).passed);
    const grade::Judge loose =
        grade::build_judge(grade::near_wide_vec3_judge(expected, {0.1L, 0.1L, 0.1L}, true));
    const grade::Verdict long_normal =
        loose(testing::result_answer(probe::vec3({0.65, 0.85, 0.0})));
    CHECK_FALSE(long_normal.passed);
    CHECK(long_normal.expected.rfind("unit (", 0) == 0);
    CHECK(grade::build_judge(grade::near_wide_vec3_judge(expected, {0.1L, 0.1L, 0.1L}))(
              testing::result_answer(probe::vec3({0.65, 0.85, 0.0})))
              .passed);
}

}  // namespace
}  // namespace raystep
