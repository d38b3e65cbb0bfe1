// Public tests for stage 1. Run them with `ctest --preset student -L stage1`, or run
// build/student/bin/raystep_stage1_tests directly to see every failure in full.
//
// One function's tests alone: `build/student/bin/raystep_stage1_tests "normalize:*"`.
//
// The loops call your function before the REQUIRE, not inside it: an exception outside a check
// ends the test at once, so a stub is reported once rather than a thousand times. Every check is
// a REQUIRE, which ends the test at its first failure: one bug prints the first input that shows
// it, not a thousand. Literal cases show their inputs in the expression. A function built from
// others names them when it fails: start with the first function whose tests fail.

#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/1_vectors/vectors.h"

using namespace raystep;
using raystep::testing::IsNear;
using raystep::testing::uses;

namespace {

constexpr double kTight = 1e-14;  // a few ulps of the values these tests use

}  // namespace

TEST_CASE("dot: multiplies componentwise and adds", "[stage1]") {
    REQUIRE(dot({1, 2, 3}, {4, -5, 6}) == 1 * 4 - 2 * 5 + 3 * 6);
    REQUIRE(dot({1, 0, 0}, {0, 1, 0}) == 0.0);
}

TEST_CASE("dot: agrees with glm::dot on random vectors", "[stage1]") {
    PortableRandom random(1);  // components in [-10, 10], seeded so a failure replays
    for (int k = 0; k < 1000; ++k) {
        const Vec3 a = random.point(10.0);
        const Vec3 b = random.point(10.0);
        CAPTURE(k, a, b);
        const double got = dot(a, b);
        REQUIRE(got == Approx(glm::dot(a, b)).epsilon(kTight).margin(kTight));
    }
}

TEST_CASE("cross: x cross y is z (right-handed)", "[stage1]") {
    REQUIRE(cross({1, 0, 0}, {0, 1, 0}) == Vec3(0, 0, 1));
    REQUIRE(cross({0, 1, 0}, {0, 0, 1}) == Vec3(1, 0, 0));
    REQUIRE(cross({0, 0, 1}, {1, 0, 0}) == Vec3(0, 1, 0));
    REQUIRE(cross({0, 1, 0}, {1, 0, 0}) == Vec3(0, 0, -1));
}

TEST_CASE("cross: is perpendicular to both and agrees with glm::cross", "[stage1]") {
    PortableRandom random(2);  // components in [-10, 10], seeded so a failure replays
    for (int k = 0; k < 1000; ++k) {
        const Vec3 a = random.point(10.0);
        const Vec3 b = random.point(10.0);
        CAPTURE(k, a, b);
        const Vec3 c = cross(a, b);
        REQUIRE_THAT(c, IsNear(glm::cross(a, b), kTight));
        REQUIRE_THAT(glm::dot(c, a), IsNear(0.0, 1e-12 * glm::length(c) * glm::length(a) + 1e-12));
        REQUIRE_THAT(glm::dot(c, b), IsNear(0.0, 1e-12 * glm::length(c) * glm::length(b) + 1e-12));
    }
}

TEST_CASE("length: of (3, 4, 12) is 13", "[stage1]") {
    REQUIRE(length({3, 4, 12}) == 13.0);
    REQUIRE(length({0, 0, 0}) == 0.0);
    REQUIRE(length({0, -2, 0}) == 2.0);
}

TEST_CASE("length: agrees with glm::length on random vectors", "[stage1]") {
    PortableRandom random(3);  // components in [-10, 10], seeded so a failure replays
    for (int k = 0; k < 1000; ++k) {
        const Vec3 v = random.point(10.0);
        CAPTURE(k, v);
        const double got = length(v);
        REQUIRE(got == Approx(glm::length(v)).epsilon(kTight));
    }
}

TEST_CASE("length: does not overflow for components near 1e200", "[stage1]") {
    INFO(
        "(3, 4, 12) * 1e200: the squares are 1e400, beyond the largest double (1.8e308), yet the "
        "length 1.3e201 is an ordinary double. sqrt(v . v) gives infinity here.");
    // Counted in units of 1e200, so that a failure prints 13 rather than 202 digits
    REQUIRE(length({3e200, 4e200, 12e200}) / 1e200 == Approx(13.0).epsilon(kTight));
}

TEST_CASE("length: does not underflow for components near 1e-200", "[stage1]") {
    INFO("The squares are 1e-400, below the smallest double (4.9e-324): sqrt(v . v) gives 0.");
    // Counted in units of 1e-200, so that a failure prints 13 rather than 0.0
    REQUIRE(length({3e-200, 4e-200, 12e-200}) / 1e-200 == Approx(13.0).epsilon(kTight));
}

TEST_CASE("normalize: gives a unit vector in the same direction", "[stage1]") {
    INFO(uses("normalize", "length"));
    REQUIRE_THAT(normalize({0, 0, -5}), IsNear(Vec3{0, 0, -1}, kTight));
    REQUIRE_THAT(normalize({3, 4, 12}), IsNear(Vec3(3, 4, 12) / 13.0, kTight));
}

TEST_CASE("normalize: agrees with glm::normalize on random vectors", "[stage1]") {
    INFO(uses("normalize", "length"));
    PortableRandom random(4);  // components in [-10, 10], seeded so a failure replays
    for (int k = 0; k < 1000; ++k) {
        const Vec3 v = random.point(10.0);
        CAPTURE(k, v);
        const Vec3 n = normalize(v);
        REQUIRE_THAT(n, IsNear(glm::normalize(v), kTight));
        REQUIRE(glm::length(n) == Approx(1.0).epsilon(kTight));
    }
}

TEST_CASE("normalize: works for tiny and huge vectors", "[stage1]") {
    INFO(uses("normalize", "length"));
    REQUIRE_THAT(normalize({3e-200, 4e-200, 12e-200}), IsNear(Vec3(3, 4, 12) / 13.0, kTight));
    REQUIRE_THAT(normalize({3e200, 4e200, 12e200}), IsNear(Vec3(3, 4, 12) / 13.0, kTight));
    REQUIRE_THAT(normalize({5e-324, 0, 0}), IsNear(Vec3{1, 0, 0}, kTight));  // the smallest double
}

TEST_CASE("normalize: the zero vector has no direction, so it throws", "[stage1]") {
    REQUIRE_THROWS_AS(normalize({0, 0, 0}), std::domain_error);
    REQUIRE_THROWS_AS(normalize({-0.0, 0, 0}), std::domain_error);
}

TEST_CASE("normalize: a vector with an infinite or NaN component throws", "[stage1]") {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    REQUIRE_THROWS_AS(normalize({inf, 0, 0}), std::domain_error);
    REQUIRE_THROWS_AS(normalize({1, nan, 0}), std::domain_error);
}

TEST_CASE("reflect: a ray hitting the floor bounces up", "[stage1]") {
    INFO(uses("reflect", "dot"));
    REQUIRE_THAT(reflect({1, -1, 0}, {0, 1, 0}), IsNear(Vec3{1, 1, 0}, kTight));
    REQUIRE_THAT(reflect({0, 0, -1}, {0, 0, 1}), IsNear(Vec3{0, 0, 1}, kTight));  // straight back
    REQUIRE_THAT(reflect({1, 0, 0}, {0, 1, 0}),
                 IsNear(Vec3{1, 0, 0}, kTight));  // grazing: unchanged
}

TEST_CASE("reflect: keeps the length and agrees with glm::reflect", "[stage1]") {
    INFO(uses("reflect", "dot"));
    PortableRandom random(5);  // components in [-10, 10], seeded so a failure replays
    for (int k = 0; k < 1000; ++k) {
        const Vec3 d = random.point(10.0);
        const Vec3 n = glm::normalize(random.point(10.0));
        CAPTURE(k, d, n);
        const Vec3 r = reflect(d, n);
        REQUIRE_THAT(r, IsNear(glm::reflect(d, n), 1e-13));
        REQUIRE(glm::length(r) == Approx(glm::length(d)).epsilon(1e-13));
    }
}

TEST_CASE("project_onto: keeps the part along the line", "[stage1]") {
    INFO(uses("project_onto", "dot and normalize"));
    REQUIRE_THAT(project_onto({3, 4, 5}, {0, 2, 0}), IsNear(Vec3{0, 4, 0}, kTight));
    REQUIRE_THAT(project_onto({1, 1, 0}, {1, 0, 0}), IsNear(Vec3{1, 0, 0}, kTight));
    REQUIRE_THAT(project_onto({0, 0, 7}, {1, 1, 0}), IsNear(Vec3{0, 0, 0}, kTight));
    REQUIRE_THAT(project_onto({2, 0, 0}, {-1, 0, 0}),
                 IsNear(Vec3{2, 0, 0}, kTight));  // onto the line, either way
}

TEST_CASE("project_onto: onto the zero vector throws", "[stage1]") {
    INFO(uses("project_onto", "dot and normalize"));
    REQUIRE_THROWS_AS(project_onto({1, 2, 3}, {0, 0, 0}), std::domain_error);
}

TEST_CASE("project_onto: a tiny or huge onto is a line like any other", "[stage1]") {
    INFO(uses("project_onto", "dot and normalize"));
    INFO("onto . onto underflows to 0 for (0, 1e-200, 0) and overflows for (0, 1e200, 0).");
    REQUIRE_THAT(project_onto({2, 3, 4}, {0, 1e-200, 0}), IsNear(Vec3{0, 3, 0}, kTight));
    REQUIRE_THAT(project_onto({2, 3, 4}, {0, 1e200, 0}), IsNear(Vec3{0, 3, 0}, kTight));
}

TEST_CASE("perpendicular_to: is what projection leaves, at right angles to the edge", "[stage1]") {
    INFO(uses("perpendicular_to", "project_onto"));
    REQUIRE_THAT(perpendicular_to({3, 4, 5}, {0, 2, 0}), IsNear(Vec3{3, 0, 5}, kTight));
    PortableRandom random(6);  // components in [-10, 10], seeded so a failure replays
    for (int k = 0; k < 1000; ++k) {
        const Vec3 v = random.point(10.0);
        const Vec3 edge = random.point(10.0);
        CAPTURE(k, v, edge);
        const Vec3 p = perpendicular_to(v, edge);
        REQUIRE_THAT(glm::dot(p, edge), IsNear(0.0, 1e-12 * glm::length(v) * glm::length(edge)));
        const Vec3 along = glm::dot(v, edge) / glm::dot(edge, edge) * edge;  // v onto the edge
        REQUIRE_THAT(p + along, IsNear(v, 1e-13));
    }
}

TEST_CASE("perpendicular_to: a zero edge throws", "[stage1]") {
    INFO(uses("perpendicular_to", "project_onto"));
    REQUIRE_THROWS_AS(perpendicular_to({1, 2, 3}, {0, 0, 0}), std::domain_error);
}

TEST_CASE("orthonormal_frame: a camera on +z looking at the origin with up +y", "[stage1]") {
    INFO(uses("orthonormal_frame", "cross, length and normalize"));
    const Frame f = orthonormal_frame({0, 0, 5}, {0, 1, 0});
    REQUIRE_THAT(f.w, IsNear(Vec3{0, 0, 1}, kTight));
    REQUIRE_THAT(f.u, IsNear(Vec3{1, 0, 0}, kTight));
    REQUIRE_THAT(f.v, IsNear(Vec3{0, 1, 0}, kTight));
}

TEST_CASE("orthonormal_frame: is orthonormal and right-handed for random input", "[stage1]") {
    INFO(uses("orthonormal_frame", "cross, length and normalize"));
    PortableRandom random(7);  // components in [-10, 10], seeded so a failure replays
    for (int k = 0; k < 1000; ++k) {
        const Vec3 a = random.point(10.0);
        const Vec3 b = random.point(10.0);
        CAPTURE(k, a, b);
        const Frame f = orthonormal_frame(a, b);
        CAPTURE(f.u, f.v);  // w should be a / |a|
        REQUIRE(glm::length(f.u) == Approx(1.0).epsilon(1e-14));
        REQUIRE(glm::length(f.v) == Approx(1.0).epsilon(1e-14));
        REQUIRE(glm::length(f.w) == Approx(1.0).epsilon(1e-14));
        REQUIRE_THAT(glm::dot(f.u, f.v), IsNear(0.0, 1e-12));
        REQUIRE_THAT(glm::dot(f.v, f.w), IsNear(0.0, 1e-12));
        REQUIRE_THAT(glm::dot(f.w, f.u), IsNear(0.0, 1e-12));
        REQUIRE_THAT(glm::cross(f.u, f.v), IsNear(f.w, 1e-12));
        REQUIRE(glm::dot(f.w, a) > 0.0);  // w points along a
        REQUIRE(glm::dot(f.v, b) > 0.0);  // v is on b's side
    }
}

TEST_CASE("orthonormal_frame: b parallel to a throws instead of returning NaN", "[stage1]") {
    INFO(uses("orthonormal_frame", "cross, length and normalize"));
    INFO("Looking straight down with \"up\" pointing up: up and view are parallel.");
    REQUIRE_THROWS_AS(orthonormal_frame({0, 10, 0}, {0, 1, 0}), std::domain_error);
    REQUIRE_THROWS_AS(orthonormal_frame({0, 10, 0}, {0, -1, 0}), std::domain_error);
}

TEST_CASE("orthonormal_frame: b parallel to a throws even when rounding hides it", "[stage1]") {
    INFO(uses("orthonormal_frame", "cross, length and normalize"));
    INFO(
        "b = 2a exactly, but w = a / |a| is rounded, so b x w is a few 1e-16, not 0: testing \"== "
        "0\" lets this through and returns a u decided by rounding alone.");
    REQUIRE_THROWS_AS(orthonormal_frame({1, 2, 3}, {2, 4, 6}), std::domain_error);
    REQUIRE_THROWS_AS(orthonormal_frame({0.1, 0.7, -0.3}, {-0.3, -2.1, 0.9}), std::domain_error);
}

TEST_CASE("orthonormal_frame: b at 1e-6 radians from a is still a frame", "[stage1]") {
    INFO(uses("orthonormal_frame", "cross, length and normalize"));
    INFO(
        "The sine 1e-6 is well above kParallelSine (1e-8): this frame is well defined. b x w = (0, "
        "-1e-6, 0), so u = (0, -1, 0) and v = w x u = (1, 0, 0), towards b.");
    const Frame f = orthonormal_frame({0, 0, 1}, {1e-6, 0, 1});
    REQUIRE_THAT(f.u, IsNear(Vec3{0, -1, 0}, 1e-9));
    REQUIRE_THAT(f.v, IsNear(Vec3{1, 0, 0}, 1e-9));
}

TEST_CASE("orthonormal_frame: parallel is decided relative to |b|", "[stage1]") {
    INFO(uses("orthonormal_frame", "cross, length and normalize"));
    INFO("A short b at right angles to a: |b x w| = 1e-10, yet the angle is 90 degrees.");
    const Frame f = orthonormal_frame({0, 0, 1}, {0, 1e-10, 0});
    REQUIRE_THAT(f.u, IsNear(Vec3{1, 0, 0}, kTight));
    REQUIRE_THAT(f.v, IsNear(Vec3{0, 1, 0}, kTight));
    // A long b 1e-10 radians from a: |b x w| = 1e-4, yet b is parallel to a.
    REQUIRE_THROWS_AS(orthonormal_frame({0, 0, 1}, {1e-4, 0, 1e6}), std::domain_error);
}

TEST_CASE("orthonormal_frame: a zero a or b throws", "[stage1]") {
    INFO(uses("orthonormal_frame", "cross, length and normalize"));
    REQUIRE_THROWS_AS(orthonormal_frame({0, 0, 0}, {0, 1, 0}), std::domain_error);
    REQUIRE_THROWS_AS(orthonormal_frame({0, 0, 1}, {0, 0, 0}), std::domain_error);
}
