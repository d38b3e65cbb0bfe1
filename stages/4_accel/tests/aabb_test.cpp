// Public tests for stage 4, the slab test. Run them with `ctest --preset student -L stage4`,
// these alone with `build/student/bin/raystep_stage4_tests "intersect_aabb:*"`.
//
// Each test calls intersect_aabb before its CHECKs: a stub ends the test case at its first call
// and is reported once. A failure prints the ray and the box; where a test tries several rays, it
// stops at the first that fails.

#include <cmath>
#include <limits>
#include <string>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "base/testing/number_text.h"
#include "base/testing/vec3_matchers.h"
#include "stages/4_accel/aabb.h"

using namespace raystep;

namespace {

// The unit cube [0, 1]^3.
const Aabb kCube{{0, 0, 0}, {1, 1, 1}};

std::string inputs(const Ray& ray, const Aabb& box) {
    using raystep::testing::exact_text;
    return "ray: origin " + exact_text(ray.origin) + ", direction " + exact_text(ray.direction) +
           ", t in [" + exact_text(ray.t_min) + ", " + exact_text(ray.t_max) + "]\nbox: min " +
           exact_text(box.min) + ", max " + exact_text(box.max);
}

std::optional<Interval> slab(const Ray& ray, const Aabb& box) {
    return intersect_aabb(ray, 1.0 / ray.direction, box);
}

// Whether the slab test reports a hit, with the inputs in the failure message; a wrong answer ends
// the test case.
void check_hits(const Ray& ray, const Aabb& box, bool expected, const char* why) {
    INFO(why);
    INFO(inputs(ray, box));
    const bool hit = slab(ray, box).has_value();
    REQUIRE(hit == expected);
}

}  // namespace

TEST_CASE("intersect_aabb: a ray through the cube enters and leaves where it should", "[stage4]") {
    const Ray ray{{0.5, 0.5, -1}, {0, 0, 1}};
    INFO(inputs(ray, kCube));
    const std::optional<Interval> hit = slab(ray, kCube);
    REQUIRE(hit);
    CHECK(hit->enter == Approx(1.0));
    CHECK(hit->exit == Approx(2.0));
}

TEST_CASE("intersect_aabb: a diagonal ray, entering through one face and leaving through another",
          "[stage4]") {
    INFO(
        "From (-1, 0.5, 0.5) along (1, 0.25, 0): enters at x = 0 (t = 1), leaves at x = 1 (t = "
        "2).");
    const Ray ray{{-1, 0.5, 0.5}, {1, 0.25, 0}};
    INFO(inputs(ray, kCube));
    const std::optional<Interval> hit = slab(ray, kCube);
    REQUIRE(hit);
    CHECK(hit->enter == Approx(1.0));
    CHECK(hit->exit == Approx(2.0));
}

TEST_CASE("intersect_aabb: misses beside, behind, and beyond t_max", "[stage4]") {
    check_hits({{2, 0.5, -1}, {0, 0, 1}}, kCube, false, "beside the cube");
    check_hits({{0.5, 0.5, -1}, {0, 0, -1}}, kCube, false, "pointing away from the cube");
    check_hits({{0.5, 0.5, -1}, {0, 0, 1}, 0.0, 0.5}, kCube, false, "stops short: enters at t = 1");
    check_hits({{-1, -1, 0.5}, {1, 3, 0}}, kCube, false, "passes beside the corner (0, 1)");
}

TEST_CASE("intersect_aabb: the interval is clipped to [t_min, t_max]", "[stage4]") {
    const Ray ray{{0.5, 0.5, -1}, {0, 0, 1}, 1.5, 1.75};
    INFO(inputs(ray, kCube));
    const std::optional<Interval> hit = slab(ray, kCube);
    REQUIRE(hit);
    CHECK(hit->enter == Approx(1.5));
    CHECK(hit->exit == Approx(1.75));
}

TEST_CASE("intersect_aabb: from inside, the interval starts at t_min", "[stage4]") {
    const Ray ray{{0.5, 0.5, 0.5}, {1, 0, 0}};
    INFO(inputs(ray, kCube));
    const std::optional<Interval> hit = slab(ray, kCube);
    REQUIRE(hit);
    CHECK(hit->enter == 0.0);
    CHECK(hit->exit == Approx(0.5));
}

TEST_CASE("intersect_aabb: a zero direction component with the origin inside that slab",
          "[stage4]") {
    check_hits({{-1, 0.5, 0.5}, {1, 0, 0}}, kCube, true,
               "D.y = 0: 1 / D.y is infinite, and (0 - 0.5) * inf = -inf, (1 - 0.5) * inf = +inf");
    check_hits({{-1, 1.5, 0.5}, {1, 0, 0}}, kCube, false,
               "D.y = 0 with the origin outside the slab 0 <= y <= 1: it never enters");
}

TEST_CASE("intersect_aabb: a zero direction component with the origin exactly on a slab plane",
          "[stage4]") {
    const Ray along_top{{-1, 1, 0.5}, {1, 0, 0}};
    {
        INFO(
            "the origin on the plane y = 1 moving along x: (1 - 1) * inf = 0 * inf = NaN. The "
            "ray runs along the box's top face, which the closed box contains: a hit from t = 1 "
            "to t = 2, not a NaN that empties the interval");
        INFO(inputs(along_top, kCube));
        const std::optional<Interval> on_top = slab(along_top, kCube);
        REQUIRE(on_top);
        CHECK(on_top->enter == Approx(1.0));
        CHECK(on_top->exit == Approx(2.0));
    }
    check_hits({{-1, 0, 0.5}, {1, -0.0, 0}}, kCube, true,
               "on the plane y = 0, with D.y = -0 (so 1 / D.y = -inf): 0 * -inf = NaN");
    check_hits({{-1, 1, 1}, {1, 0, 0}}, kCube, true,
               "along the edge y = 1, z = 1: two NaN slabs at once");
}

TEST_CASE("intersect_aabb: a ray in any face's plane keeps its t_min and t_max", "[stage4]") {
    INFO(
        "The NaN of 0 * inf comes from whichever axis the ray lies across, on the min or the max "
        "plane, with D = +0 or -0. Taken as a bound (std::max(t_near, enter) returns its NaN first "
        "argument) it empties the interval when it comes last, from z, and otherwise lets the next "
        "axis overwrite t_min and t_max.");
    for (int axis = 0; axis < 3; ++axis) {
        for (const double plane : {0.0, 1.0}) {
            for (const double zero : {0.0, -0.0}) {
                const int along = (axis + 1) % 3;
                Vec3 origin(0.5);
                origin[axis] = plane;
                origin[along] = -1;
                Vec3 direction(0.0);
                direction[axis] = zero;
                direction[along] = 1;
                const Ray ray{origin, direction, 1.25, 1.75};
                INFO("axis " << axis << ", the plane " << plane << ", D = " << zero);
                INFO(inputs(ray, kCube));
                const std::optional<Interval> hit = slab(ray, kCube);
                REQUIRE(hit);
                REQUIRE(hit->enter == 1.25);
                REQUIRE(hit->exit == Approx(1.75));
            }
        }
    }
}

TEST_CASE("intersect_aabb: a flat box (zero thickness) is still hit", "[stage4]") {
    const Aabb flat{{0, 0, 0}, {1, 1, 0}};  // a triangle's box in the plane z = 0
    const Ray ray{{0.5, 0.5, 1}, {0, 0, -1}};
    INFO(inputs(ray, flat));
    const std::optional<Interval> hit = slab(ray, flat);
    REQUIRE(hit);
    CHECK(hit->enter == Approx(1.0));
    CHECK(hit->exit == Approx(1.0));
}

TEST_CASE("intersect_aabb: an empty box is never hit", "[stage4]") {
    check_hits({{0.5, 0.5, -1}, {0, 0, 1}}, Aabb{}, false,
               "Aabb{} is empty: min = +inf, max = -inf, so no t is in every slab");
}

TEST_CASE("intersect_aabb: rays that touch a box's edge or corner are never lost to rounding",
          "[stage4]") {
    INFO(
        "Rays from random origins aimed exactly at a corner or at a point of an edge of a box "
        "whose coordinates are not round in binary: rounding in (bound - A) / D must not make the "
        "exit come out before the entry.");
    PortableRandom random(41);
    const Aabb box{{0.1, 0.2, 0.3}, {0.7, 1.3, 2.9}};
    for (int k = 0; k < 20000; ++k) {
        const Vec3 origin = random.point(10.0);
        const double s = random.unit();
        const Vec3 target =
            k % 2 == 0 ? box.max
                       : Vec3(box.min.x, box.min.y, box.min.z + s * (box.max.z - box.min.z));
        const Ray ray{origin, target - origin};
        CAPTURE(k);
        INFO(inputs(ray, box));
        const bool hit = slab(ray, box).has_value();
        REQUIRE(hit);
    }
}
