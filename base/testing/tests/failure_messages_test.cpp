// What a failing public test prints (base/testing/): numbers that read at a glance, tolerances at
// their size, and the functions a test's function is built from. docs/measurements/
// failure-output.md measures whole test programs on bugs; these pin down the pieces.

#include <limits>

#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/number_text.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"

using namespace raystep;
using namespace raystep::testing;

TEST_CASE("exact_text: the shortest text that reads back as the same double", "[base]") {
    CHECK(exact_text(0.1) == "0.1");
    CHECK(exact_text(0.1 + 0.2) == "0.30000000000000004");
    CHECK(exact_text(13.0) == "13");
    INFO("Catch2 prints these in fixed notation: 0.0, and 202 digits");
    CHECK(exact_text(1e-15) == "1e-15");
    CHECK(exact_text(1.3e201) == "1.3e+201");
    CHECK(exact_text(std::numeric_limits<double>::infinity()) == "inf");
    CHECK(exact_text(Vec3(1, 0.5, -2e-9)) == "(1, 0.5, -2e-09)");
}

TEST_CASE("size_text: a tolerance to 3 digits, never 0.0", "[base]") {
    CHECK(size_text(1e-15) == "1e-15");
    CHECK(size_text(0.25) == "0.25");
    CHECK(size_text(1.0 / 3.0 * 1e-12) == "3.33e-13");
}

TEST_CASE("IsNear: a failed vector check shows the distance it allowed", "[base]") {
    CHECK(IsNear(Vec3(0, 0, 1), 1e-15).describe() == "is within 1e-15 of (0, 0, 1)");
    INFO("above a length of 1, the tolerance is relative: 1e-14 of |(3, 4, 12)| = 13");
    CHECK(IsNear(Vec3(3, 4, 12), 1e-14).describe() == "is within 1.3e-13 of (3, 4, 12)");
    CHECK(Catch::Detail::stringify(Vec3(3e200, 0.1, 0)) == "(3e+200, 0.1, 0)");
}

TEST_CASE("IsNear: a failed number check shows the tolerance and how far off it was", "[base]") {
    const NearNumber near_zero = IsNear(0.0, 4e-16);
    CHECK_FALSE(near_zero.match(1.1e-15));
    CHECK(near_zero.describe() == "is within 4e-16 of 0, off by 1.1e-15");
    CHECK(IsNear(1.0, 4e-16).match(1.0 + 0x1p-52));
    CHECK_FALSE(IsNear(0.0, 1.0).match(std::numeric_limits<double>::quiet_NaN()));
    CHECK(IsNear(100.0, 1e-3).match(100.09));  // within 1e-3 x 100
}

TEST_CASE("uses: one line naming what to fix first", "[base]") {
    CHECK(uses("orthonormal_frame", "cross, length and normalize") ==
          "orthonormal_frame uses cross, length and normalize: fix their failures first");
}
