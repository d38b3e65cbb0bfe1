// The grader's inputs written as C++ for a student's test: every digit, and names a student's
// code has.

#include "grader/grade/checks/cpp_literal.h"

#include <cmath>
#include <cstdlib>
#include <limits>

#include "base/testing/catch.h"

using namespace raystep;
using namespace raystep::grade;

TEST_CASE("cpp: a double reads back as the same double", "[grader]") {
    for (const double x : {0.1, -1.0 / 3.0, 1e-320, 5e200, 3.0, -0.0}) {
        CAPTURE(x);
        const std::string text = cpp(x);
        CHECK(std::strtod(text.c_str(), nullptr) == x);
        CHECK(std::signbit(std::strtod(text.c_str(), nullptr)) == std::signbit(x));
    }
    CHECK(cpp(std::numeric_limits<double>::infinity()) == "INFINITY");
    CHECK(cpp(-std::numeric_limits<double>::infinity()) == "-INFINITY");
    CHECK(cpp(std::nan("")) == "NAN");
}

TEST_CASE("cpp: calls read as the student's API spells them", "[grader]") {
    CHECK(cpp(Vec3{1, 2.5, -3}) == "{1, 2.5, -3}");
    CHECK(cpp(Ray{{0, 0, 5}, {0, 0, -1}, 0.25, std::numeric_limits<double>::infinity()}) ==
          "Ray{{0, 0, 5}, {0, 0, -1}, 0.25, INFINITY}");
    CHECK(cpp(TransformOp{TransformOp::Kind::rotate, {0, 0, 1}, 90}) ==
          "TransformOp{TransformOp::Kind::rotate, {0, 0, 1}, 90}");
    CHECK(cpp(RayOffset{OffsetRule::along_normal, 1e-4}) ==
          "RayOffset{OffsetRule::along_normal, 0.0001}");
    // glm's 16-number constructor takes the matrix column by column.
    Mat4 m(1.0);
    m[3][0] = 7;
    CHECK(cpp(m) == "Mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 7, 0, 0, 1)");
}
