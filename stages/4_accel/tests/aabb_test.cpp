// Public tests for stage 4, the slab test. Run them with `ctest --preset release -L stage4`.

#include <cmath>
#include <limits>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "stages/4_accel/aabb.h"

using namespace raystep;

namespace {

const double kInf = std::numeric_limits<double>::infinity();

// The unit cube [0, 1]^3.
const Aabb kCube{{0, 0, 0}, {1, 1, 1}};

std::optional<Interval> slab(const Ray& ray, const Aabb& box) {
    return intersect_aabb(ray, 1.0 / ray.direction, box);
}

}  // namespace

TEST_CASE("intersect_aabb: a ray through the cube enters and leaves where it should", "[stage4]") {
    const std::optional<Interval> hit = slab({{0.5, 0.5, -1}, {0, 0, 1}}, kCube);
    REQUIRE(hit);
    CHECK(hit->enter == Approx(1.0));
    CHECK(hit->exit == Approx(2.0));
}

TEST_CASE("intersect_aabb: a diagonal ray, entering through one face and leaving through another",
          "[stage4]") {
    // From (-1, 0.5, 0.5) along (1, 0.25, 0): enters at x = 0 (t = 1), leaves at x = 1 (t = 2).
    const std::optional<Interval> hit = slab({{-1, 0.5, 0.5}, {1, 0.25, 0}}, kCube);
    REQUIRE(hit);
    CHECK(hit->enter == Approx(1.0));
    CHECK(hit->exit == Approx(2.0));
}

TEST_CASE("intersect_aabb: misses beside, behind, and beyond t_max", "[stage4]") {
    CHECK_FALSE(slab({{2, 0.5, -1}, {0, 0, 1}}, kCube));              // beside
    CHECK_FALSE(slab({{0.5, 0.5, -1}, {0, 0, -1}}, kCube));           // pointing away
    CHECK_FALSE(slab({{0.5, 0.5, -1}, {0, 0, 1}, 0.0, 0.5}, kCube));  // stops short
    CHECK_FALSE(slab({{-1, -1, 0.5}, {1, 3, 0}}, kCube));             // passes the corner
}

TEST_CASE("intersect_aabb: the interval is clipped to [t_min, t_max]", "[stage4]") {
    const std::optional<Interval> hit = slab({{0.5, 0.5, -1}, {0, 0, 1}, 1.5, 1.75}, kCube);
    REQUIRE(hit);
    CHECK(hit->enter == Approx(1.5));
    CHECK(hit->exit == Approx(1.75));
}

TEST_CASE("intersect_aabb: from inside, the interval starts at t_min", "[stage4]") {
    const std::optional<Interval> hit = slab({{0.5, 0.5, 0.5}, {1, 0, 0}}, kCube);
    REQUIRE(hit);
    CHECK(hit->enter == 0.0);
    CHECK(hit->exit == Approx(0.5));
}

TEST_CASE("intersect_aabb: a zero direction component with the origin inside that slab",
          "[stage4]") {
    // D.y = 0: 1 / D.y is infinite, and (0 - 0.5) * inf = -inf, (1 - 0.5) * inf = +inf.
    CHECK(slab({{-1, 0.5, 0.5}, {1, 0, 0}}, kCube));
    CHECK_FALSE(slab({{-1, 1.5, 0.5}, {1, 0, 0}}, kCube));  // outside that slab: never enters
}

TEST_CASE("intersect_aabb: a zero direction component with the origin exactly on a slab plane",
          "[stage4]") {
    // The origin on the plane y = 1 moving along x: (1 - 1) * inf = 0 * inf = NaN. The ray
    // runs along the box's top face, which the closed box contains: a hit, not a NaN that
    // empties the interval.
    const std::optional<Interval> on_top = slab({{-1, 1, 0.5}, {1, 0, 0}}, kCube);
    REQUIRE(on_top);
    CHECK(on_top->enter == Approx(1.0));
    CHECK(on_top->exit == Approx(2.0));
    // On the plane y = 0, with D.y = -0 (so 1 / D.y = -inf): the same.
    CHECK(slab({{-1, 0, 0.5}, {1, -0.0, 0}}, kCube));
    // Along the edge y = 1, z = 1: two NaN slabs at once.
    CHECK(slab({{-1, 1, 1}, {1, 0, 0}}, kCube));
}

TEST_CASE("intersect_aabb: a ray in any face's plane keeps its t_min and t_max", "[stage4]") {
    // The NaN of 0 * inf comes from whichever axis the ray lies across, on the min or the max
    // plane, with D = +0 or -0. Taken as a bound (std::max(t_near, enter) returns its NaN first
    // argument) it empties the interval when it comes last, from z, and otherwise lets the next
    // axis overwrite t_min and t_max.
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
                INFO("axis " << axis << ", the plane " << plane << ", D = " << zero);
                const std::optional<Interval> hit = slab({origin, direction, 1.25, 1.75}, kCube);
                REQUIRE(hit);
                CHECK(hit->enter == 1.25);
                CHECK(hit->exit == Approx(1.75));
            }
        }
    }
}

TEST_CASE("intersect_aabb: a flat box (zero thickness) is still hit", "[stage4]") {
    const Aabb flat{{0, 0, 0}, {1, 1, 0}};  // a triangle's box in the plane z = 0
    const std::optional<Interval> hit = slab({{0.5, 0.5, 1}, {0, 0, -1}}, flat);
    REQUIRE(hit);
    CHECK(hit->enter == Approx(1.0));
    CHECK(hit->exit == Approx(1.0));
}

TEST_CASE("intersect_aabb: an empty box is never hit", "[stage4]") {
    CHECK_FALSE(slab({{0.5, 0.5, -1}, {0, 0, 1}}, Aabb{}));
}

TEST_CASE("intersect_aabb: rays that touch a box's edge or corner are never lost to rounding",
          "[stage4]") {
    // Rays from random origins aimed exactly at a corner or at a point of an edge of a box whose
    // coordinates are not round in binary: rounding in (bound - A) / D must not make the exit come
    // out before the entry.
    PortableRandom random(41);
    const Aabb box{{0.1, 0.2, 0.3}, {0.7, 1.3, 2.9}};
    for (int k = 0; k < 20000; ++k) {
        const Vec3 origin = random.point(10.0);
        const double s = random.unit();
        const Vec3 target =
            k % 2 == 0 ? box.max
                       : Vec3(box.min.x, box.min.y, box.min.z + s * (box.max.z - box.min.z));
        const Ray ray{origin, target - origin};
        CAPTURE(k, origin.x, origin.y, origin.z);
        CHECK(slab(ray, box).has_value());
    }
}
