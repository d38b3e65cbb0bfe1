// An expectation kept in double-double, written into a release's case file and read back: every
// bit kept, the same on every platform, so that a release judges by the number the grader decided
// and gives the verdict the grader gives, even within half an ulp of a tolerance.

#include <cmath>
#include <cstring>
#include <set>
#include <string>

#include "base/testing/catch.h"

#include "app/grade/data_judge.h"
#include "app/grade/value_judges.h"
#include "app/probe/tests/probe_answers.h"
#include "app/protocol/wide_json.h"

namespace raystep {
namespace {

bool same_bits(const DoubleDouble& a, const DoubleDouble& b) {
    return std::memcmp(&a.hi, &b.hi, sizeof a.hi) == 0 &&
           std::memcmp(&a.lo, &b.lo, sizeof a.lo) == 0;
}

// A near_wide_number judge as a release's case file holds it, read from its text.
grade::Judge number_judge_from_text(const std::string& expected, const std::string& tolerance) {
    return grade::build_judge(probe::Json::parse(R"({"judge": "near_wide_number", "expected": )" +
                                                 expected + R"(, "tolerance": )" + tolerance +
                                                 "}"));
}

bool passes(const grade::Judge& judge, double got) {
    return judge(testing::result_answer(probe::number(got))).passed;
}

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

TEST_CASE("a double-double survives its [hi, lo] pair bit for bit") {
    const DoubleDouble root = sqrt(DoubleDouble(2.0));
    REQUIRE(root.lo != 0);
    const probe::Json written = probe::wide(root);
    CHECK(same_bits(probe::wide_from(written), root));
    CHECK(same_bits(probe::wide_from(probe::Json::parse(written.dump())), root));
    CHECK(is_infinite(probe::wide_from(probe::wide(DoubleDouble(HUGE_VAL)))));
    CHECK(std::isnan(probe::wide_from(probe::wide(DoubleDouble(std::nan("")))).hi));
    CHECK(std::signbit(probe::wide_from(probe::wide(DoubleDouble(-0.0))).hi));
    CHECK_THROWS_AS(probe::wide_from(probe::Json(0.5)), std::invalid_argument);
    CHECK_THROWS_AS(probe::wide_from(probe::Json::parse(R"([1, "inf"])")), std::invalid_argument);
}

TEST_CASE("a case file's [hi, lo] text reads as the same two doubles on every platform") {
    // 1/3: hi the nearest double, lo the rest rounded, as the grader writes them.
    const DoubleDouble third =
        probe::wide_from(probe::Json::parse("[0.3333333333333333, 1.850371707708594e-17]"));
    CHECK(same_bits(third, DoubleDouble(0x1.5555555555555p-2, 0x1.5555555555555p-56)));
    // A pair that is not normalized reads as its sum.
    CHECK(same_bits(probe::wide_from(probe::Json::parse("[1, 1]")), DoubleDouble(2.0)));
    CHECK(same_bits(probe::wide_from(probe::Json::parse("[1, 8.673617379884035e-19]")),
                    DoubleDouble(1.0, 0x1p-60)));
}

TEST_CASE("near_wide_number: within half an ulp of the tolerance, the bits below a double decide") {
    // The expectation 1 + 2^-60, whose nearest double is 1. Judged by that double, as a platform
    // whose long double is a double would judge it, each answer below gets the other verdict; in
    // x86-64's 80-bit long double and in double-double, this one.
    const std::string expected = "[1, 8.673617379884035e-19]";

    // 1 - 2^-53 is 2^-53 + 2^-60 from it: just beyond a tolerance of 2^-53.
    const double below = 0.9999999999999999;
    REQUIRE(below == 1 - 0x1p-53);
    CHECK(std::abs(below - 1.0) <= 0x1p-53);  // the rounded expectation's verdict
    CHECK_FALSE(passes(number_judge_from_text(expected, "[1.1102230246251565e-16, 0]"), below));

    // 1 + 2^-52 is 2^-52 - 2^-60 from it: just within a tolerance of exactly that.
    const double above = 1.0000000000000002;
    REQUIRE(above == 1 + 0x1p-52);
    const double tolerance = 0x1p-52 - 0x1p-60;
    CHECK_FALSE(std::abs(above - 1.0) <= tolerance);  // the rounded expectation's verdict
    CHECK(passes(number_judge_from_text(expected, "[2.211772431870429e-16, 0]"), above));
}

TEST_CASE("a wide judge compares in double-double, the bits below a double's included") {
    // 1 + 2^-60 within 2^-62: the double 1 is 2^-60 away, a judge by the rounded 1 would pass it.
    const DoubleDouble expected = two_sum(1, 0x1p-60);
    const grade::Judge number =
        grade::build_judge(grade::near_wide_number_judge(expected, DoubleDouble(0x1p-62)));
    CHECK_FALSE(passes(number, 1.0));
    CHECK(passes(grade::build_judge(grade::near_wide_number_judge(expected, DoubleDouble(0x1p-59))),
                 1.0));
    // Bits a long double would not hold: 1 + 2^-80 within 2^-82 fails 1 too.
    CHECK_FALSE(passes(grade::build_judge(grade::near_wide_number_judge(two_sum(1, 0x1p-80),
                                                                        DoubleDouble(0x1p-82))),
                       1.0));
}

TEST_CASE("a wide vector judge fails a NaN, a component out of tolerance and a non-unit normal") {
    const DoubleDoubleVec3 expected{0.6, 0.8, 0.0};
    const DoubleDoubleVec3 tolerance(1e-15);
    const grade::Judge unit =
        grade::build_judge(grade::near_wide_vec3_judge(expected, tolerance, true));
    CHECK(unit(testing::result_answer(probe::vec3({0.6, 0.8, 0.0}))).passed);
    CHECK_FALSE(unit(testing::result_answer(probe::vec3({0.6, 0.8, std::nan("")}))).passed);
    CHECK_FALSE(unit(testing::result_answer(probe::vec3({0.6, 0.81, 0.0}))).passed);
    const grade::Judge loose =
        grade::build_judge(grade::near_wide_vec3_judge(expected, DoubleDoubleVec3(0.1), true));
    const grade::Verdict long_normal =
        loose(testing::result_answer(probe::vec3({0.65, 0.85, 0.0})));
    CHECK_FALSE(long_normal.passed);
    CHECK(long_normal.expected.rfind("unit (", 0) == 0);
    CHECK(grade::build_judge(grade::near_wide_vec3_judge(expected, DoubleDoubleVec3(0.1)))(
              testing::result_answer(probe::vec3({0.65, 0.85, 0.0})))
              .passed);
}

}  // namespace
}  // namespace raystep
