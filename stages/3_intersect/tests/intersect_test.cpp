// Public tests for stage 3, planes, spheres and the closest hit; the triangle tests are in
// triangle_test.cpp. Run them with `ctest --preset student -L stage3`, one function's with
// `build/student/bin/raystep_stage3_tests "intersect_sphere:*"`.
//
// Each test calls your function before its CHECKs: a stub ends the test case at its first call
// and is reported once. A failure prints the ray and the primitive it was given; where a test
// tries several rays, it stops at the first that fails. The tests of a function built from others
// name them: start with the first function whose tests fail.

#include <limits>
#include <optional>
#include <string>

#include "base/testing/catch.h"
#include "base/testing/number_text.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/3_intersect/intersect.h"
#include "stages/3_intersect/tests/hit_text.h"

using namespace raystep;
using raystep::testing::exact_text;
using raystep::testing::IsNear;
using raystep::testing::text;
using raystep::testing::uses;

namespace {

const double kInf = std::numeric_limits<double>::infinity();

std::string inputs(const Ray& ray, const Plane& plane) {
    return text(ray) + "\nplane: point " + exact_text(plane.point) + ", normal " +
           exact_text(plane.normal);
}

std::string inputs(const Ray& ray, const Sphere& sphere) {
    return text(ray) + "\nsphere: centre " + exact_text(sphere.center) + ", radius " +
           exact_text(sphere.radius);
}

// Whether intersect_plane reports a hit, with the inputs in the failure message; a wrong answer
// ends the test case.
void check_plane_hits(const Ray& ray, const Plane& plane, bool expected, const char* why) {
    INFO(why);
    INFO(inputs(ray, plane));
    const bool hit = intersect_plane(ray, plane).has_value();
    REQUIRE(hit == expected);
}

// Whether intersect_sphere reports a hit, with the inputs in the failure message; a wrong answer
// ends the test case.
void check_sphere_hits(const Ray& ray, const Sphere& sphere, bool expected, const char* why) {
    INFO(why);
    INFO(inputs(ray, sphere));
    const bool hit = intersect_sphere(ray, sphere).has_value();
    REQUIRE(hit == expected);
}

}  // namespace

TEST_CASE("intersect_plane: hits the floor at the distance down to it", "[stage3]") {
    INFO(uses("intersect_plane", "stage 1's dot and normalize"));
    const Plane floor{{0, -1, 0}, {0, 2, 0}};  // y = -1, normal of length 2
    const Ray ray{{0, 3, 0}, {0, -1, 0}};
    INFO("from y = 3 straight down to y = -1: t = 4, and the normal is unit length");
    INFO(inputs(ray, floor));
    const std::optional<Hit> hit = intersect_plane(ray, floor);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK_THAT(hit->normal, IsNear(Vec3{0, 1, 0}, 1e-15));
}

TEST_CASE("intersect_plane: a ray parallel to the plane misses", "[stage3]") {
    INFO(uses("intersect_plane", "stage 1's dot and normalize"));
    const Plane floor{{0, 0, 0}, {0, 1, 0}};
    check_plane_hits({{0, 1, 0}, {1, 0, 0}}, floor, false, "parallel, above the plane");
    check_plane_hits({{0, 0, 0}, {1, 0, 0}}, floor, false, "parallel, lying in the plane");
}

TEST_CASE("intersect_plane: a plane behind the ray or beyond t_max misses", "[stage3]") {
    INFO(uses("intersect_plane", "stage 1's dot and normalize"));
    const Plane floor{{0, 0, 0}, {0, 1, 0}};
    check_plane_hits({{0, 1, 0}, {0, 1, 0}}, floor, false, "the plane is behind the ray");
    check_plane_hits({{0, 1, 0}, {0, -1, 0}, 0.0, 0.5}, floor, false,
                     "the hit at t = 1 is beyond t_max");
    check_plane_hits({{0, 1, 0}, {0, -1, 0}, 0.0, 1.0}, floor, true,
                     "the hit at t = 1 is at t_max: the range is closed");
}

TEST_CASE("intersect_plane: a zero direction misses", "[stage3]") {
    INFO(uses("intersect_plane", "stage 1's dot and normalize"));
    check_plane_hits({{0, 1, 0}, {0, 0, 0}}, {{0, 0, 0}, {0, 1, 0}}, false,
                     "a zero direction goes nowhere");
}

TEST_CASE("intersect_sphere: a ray at the centre hits the near side", "[stage3]") {
    INFO(uses("intersect_sphere", "stage 1's dot"));
    const Ray ray{{0, 0, 5}, {0, 0, -1}};
    const Sphere sphere{{0, 0, 0}, 1.0};
    INFO("expected t = 4 and the normal (0, 0, 1) at the near side");
    INFO(inputs(ray, sphere));
    const std::optional<Hit> hit = intersect_sphere(ray, sphere);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK_THAT(hit->normal, IsNear(Vec3{0, 0, 1}, 1e-15));
}

TEST_CASE("intersect_sphere: t is in units of the direction's length", "[stage3]") {
    INFO(uses("intersect_sphere", "stage 1's dot"));
    const Ray ray{{0, 0, 5}, {0, 0, -2}};
    const Sphere sphere{{0, 0, 0}, 1.0};
    INFO("the near side is 4 away and the direction 2 long: t = 2, not 4");
    INFO(inputs(ray, sphere));
    const std::optional<Hit> hit = intersect_sphere(ray, sphere);
    REQUIRE(hit);
    CHECK(hit->t == Approx(2.0));
}

TEST_CASE("intersect_sphere: from inside, the ray hits the far side", "[stage3]") {
    INFO(uses("intersect_sphere", "stage 1's dot"));
    const Ray ray{{0, 0, 0}, {1, 0, 0}};
    const Sphere sphere{{0, 0, 0}, 2.0};
    INFO("from the centre: t = 2, and the normal points outward, (1, 0, 0), not towards the ray");
    INFO(inputs(ray, sphere));
    const std::optional<Hit> hit = intersect_sphere(ray, sphere);
    REQUIRE(hit);
    CHECK(hit->t == Approx(2.0));
    CHECK_THAT(hit->normal, IsNear(Vec3{1, 0, 0}, 1e-15));
}

TEST_CASE("intersect_sphere: a near root before t_min gives way to the far root", "[stage3]") {
    INFO(uses("intersect_sphere", "stage 1's dot"));
    const Ray ray{{0, 0, 5}, {0, 0, -1}, 4.5, kInf};
    const Sphere sphere{{0, 0, 0}, 1.0};
    INFO("the roots are t = 4 and t = 6; t_min = 4.5 leaves the far one, t = 6");
    INFO(inputs(ray, sphere));
    const std::optional<Hit> hit = intersect_sphere(ray, sphere);
    REQUIRE(hit);
    CHECK(hit->t == Approx(6.0));
}

TEST_CASE("intersect_sphere: misses a sphere beside the ray or behind it", "[stage3]") {
    INFO(uses("intersect_sphere", "stage 1's dot"));
    check_sphere_hits({{0, 2, 5}, {0, 0, -1}}, {{0, 0, 0}, 1.0}, false,
                      "the ray passes 2 from the centre of a sphere of radius 1");
    check_sphere_hits({{0, 0, 5}, {0, 0, 1}}, {{0, 0, 0}, 1.0}, false,
                      "the sphere is behind the ray: both roots are negative");
}

TEST_CASE("intersect_sphere: a tangent ray touches the sphere once", "[stage3]") {
    INFO(uses("intersect_sphere", "stage 1's dot"));
    const Ray ray{{0, 1, 5}, {0, 0, -1}};
    const Sphere sphere{{0, 0, 0}, 1.0};
    INFO("the ray grazes the top of the sphere: a double root at t = 5, normal (0, 1, 0)");
    INFO(inputs(ray, sphere));
    const std::optional<Hit> hit = intersect_sphere(ray, sphere);
    REQUIRE(hit);
    CHECK(hit->t == Approx(5.0));
    CHECK_THAT(hit->normal, IsNear(Vec3{0, 1, 0}, 1e-7));
}

TEST_CASE("intersect_sphere: a zero radius or a zero direction misses, never NaN", "[stage3]") {
    INFO(uses("intersect_sphere", "stage 1's dot"));
    check_sphere_hits({{0, 0, 5}, {0, 0, -1}}, {{0, 0, 0}, 0.0}, false,
                      "a sphere of radius 0 has no surface to hit");
    check_sphere_hits({{0, 0, 5}, {0, 0, 0}}, {{0, 0, 0}, 1.0}, false,
                      "a zero direction goes nowhere (a = 0 in the quadratic)");
}

TEST_CASE("intersect_sphere: a ray starting just outside a large sphere hits it at a tiny t",
          "[stage3]") {
    INFO(uses("intersect_sphere", "stage 1's dot"));
    const Sphere large{{0, 0, 0}, 5e7};
    const Ray ray{{1, 5e7, 0}, {0, -1, 0}};
    INFO(
        "radius 5e7, the origin 1 unit beside the top of the sphere, going down: the near root "
        "is t = c / q = 1 / (5e7 + sqrt(2.5e15 - 1)) = 1e-8, and every intermediate here is "
        "exact. The textbook -b - sqrt(b^2 - 4ac) subtracts two numbers near 1e8 that differ "
        "by 2e-8 and gets 7.45e-9, 25% short; the stable form q = -(b + sign(b) sqrt(...)) has "
        "nothing to cancel. See docs/stage3.md, \"Ray-sphere\".");
    INFO(inputs(ray, large));
    const std::optional<Hit> hit = intersect_sphere(ray, large);
    REQUIRE(hit);
    // t in units of 1e-8, so that a failure prints 0.745 rather than 0.0000000075
    CHECK(hit->t * 1e8 == Approx(1.0).epsilon(1e-12));
    CHECK_THAT(hit->normal, IsNear(Vec3(2e-8, 1, 0), 1e-12));
}

TEST_CASE("intersect_sphere: a small sphere far away, hit to the nanometre", "[stage3]") {
    INFO(uses("intersect_sphere", "stage 1's dot"));
    const Sphere sphere{{1e5, 0, 0}, 1e-3};
    INFO(
        "a 1 mm sphere 100 km away: b^2 and a c are both near 1e10, and b^2 - a c keeps only a "
        "few of its digits, a fraction of a millimetre. Written as a (r^2 - |f - (b / a) D|^2), "
        "r^2 minus the squared distance from the centre to the ray's line, it has nothing to "
        "cancel.");
    {
        INFO("through the centre: t = 1e5 - 1e-3 = 99999.999");
        const Ray ray{{0, 0, 0}, {1, 0, 0}};
        INFO(inputs(ray, sphere));
        const std::optional<Hit> hit = intersect_sphere(ray, sphere);
        REQUIRE(hit);
        CHECK(hit->t == Approx(99999.999).margin(1e-9));
    }
    {
        INFO("0.6 r from the centre: t = 1e5 - sqrt(r^2 - 0.6e-3^2) = 99999.9992");
        const Ray ray{{0, 0.6e-3, 0}, {1, 0, 0}};
        INFO(inputs(ray, sphere));
        const std::optional<Hit> hit = intersect_sphere(ray, sphere);
        REQUIRE(hit);
        CHECK(hit->t == Approx(99999.9992).margin(1e-9));
        CHECK_THAT(hit->normal, IsNear(Vec3(-0.8, 0.6, 0), 1e-5));
    }
    {
        INFO("1.00001 r from the centre: a miss, which b^2 - a c cannot tell from a hit");
        check_sphere_hits({{0, 1.00001e-3, 0}, {1, 0, 0}}, sphere, false,
                          "the line passes 1.00001 r from the centre");
    }
}

TEST_CASE("intersect_sphere: a huge sphere is hit where it should be", "[stage3]") {
    INFO(uses("intersect_sphere", "stage 1's dot"));
    const Sphere ground{{0, -1e6, 0}, 1e6};
    const Ray ray{{0, 10, 0}, {0, -1, 0}};
    INFO(
        "the ground as a sphere of radius 1e6 centred 1e6 below the origin: from y = 10 down, "
        "t = 10 and the normal (0, 1, 0)");
    INFO(inputs(ray, ground));
    const std::optional<Hit> hit = intersect_sphere(ray, ground);
    REQUIRE(hit);
    CHECK(hit->t == Approx(10.0).epsilon(1e-9));
    CHECK_THAT(hit->normal, IsNear(Vec3{0, 1, 0}, 1e-9));
}

TEST_CASE("closest_hit: returns the nearest of several primitives", "[stage3]") {
    INFO(uses("closest_hit", "the intersect_* functions"));
    PrimitiveList list;
    list.spheres = {{{0, 0, -10}, 1.0}, {{0, 0, -4}, 1.0}};
    list.triangles = {{{-1, -1, -6}, {1, -1, -6}, {0, 1, -6}}};
    list.planes = {{{0, 0, -20}, {0, 0, 1}}};
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    INFO(text(ray) +
         "\nspheres at z = -10 and -4 (radius 1), a triangle at z = -6, a plane at "
         "z = -20: the nearest is sphere 1, at t = 3");
    const std::optional<PrimitiveHit> hit = closest_hit(ray, list);
    INFO("closest_hit found " << text(hit));
    REQUIRE(hit);
    REQUIRE(hit->kind == PrimitiveKind::sphere);
    REQUIRE(hit->index == 1);
    REQUIRE(hit->hit.t == Approx(3.0));
}

TEST_CASE("closest_hit: a triangle or a plane can be nearest too", "[stage3]") {
    INFO(uses("closest_hit", "the intersect_* functions"));
    PrimitiveList list;
    list.spheres = {{{0, 0, -10}, 1.0}};
    list.triangles = {{{-1, -1, -6}, {1, -1, -6}, {0, 1, -6}},
                      {{-1, -1, -5}, {1, -1, -5}, {0, 1, -5}}};
    list.planes = {{{0, 0, -20}, {0, 0, 1}}};
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    {
        INFO("triangle 1, at z = -5, before the other triangle, the sphere and the plane");
        INFO(text(ray));
        const std::optional<PrimitiveHit> hit = closest_hit(ray, list);
        INFO("closest_hit found " << text(hit));
        REQUIRE(hit);
        REQUIRE(hit->kind == PrimitiveKind::triangle);
        REQUIRE(hit->index == 1);
        REQUIRE(hit->hit.t == Approx(5.0));
    }
    {
        INFO("plane 1, at z = -2, before everything else");
        list.planes.push_back({{0, 0, -2}, {0, 0, 1}});
        INFO(text(ray));
        const std::optional<PrimitiveHit> hit = closest_hit(ray, list);
        INFO("closest_hit found " << text(hit));
        REQUIRE(hit);
        REQUIRE(hit->kind == PrimitiveKind::plane);
        REQUIRE(hit->index == 1);
    }
}

TEST_CASE("closest_hit: respects the ray's [t_min, t_max]", "[stage3]") {
    INFO(uses("closest_hit", "the intersect_* functions"));
    PrimitiveList list;
    list.spheres = {{{0, 0, -4}, 1.0}};
    list.planes = {{{0, 0, -8}, {0, 0, 1}}};
    {
        INFO("the sphere's near side (t = 3) is before t_min: its far side (t = 5) is nearest");
        const Ray ray{{0, 0, 0}, {0, 0, -1}, 4.0, kInf};
        INFO(text(ray));
        const std::optional<PrimitiveHit> hit = closest_hit(ray, list);
        INFO("closest_hit found " << text(hit));
        REQUIRE(hit);
        REQUIRE(hit->hit.t == Approx(5.0));
    }
    {
        INFO("everything is beyond t_max = 2: no hit");
        const Ray ray{{0, 0, 0}, {0, 0, -1}, 0.0, 2.0};
        INFO(text(ray));
        const std::optional<PrimitiveHit> hit = closest_hit(ray, list);
        INFO("closest_hit found " << text(hit));
        REQUIRE_FALSE(hit);
    }
}

TEST_CASE("closest_hit: an empty list or a ray that misses everything gives no hit", "[stage3]") {
    INFO(uses("closest_hit", "the intersect_* functions"));
    const std::optional<PrimitiveHit> in_empty = closest_hit({{0, 0, 0}, {0, 0, -1}}, {});
    INFO("closest_hit found " << text(in_empty));
    REQUIRE_FALSE(in_empty);
    PrimitiveList list;
    list.spheres = {{{0, 0, -4}, 1.0}};
    const Ray ray{{0, 0, 0}, {0, 1, 0}};
    INFO(text(ray) + "\na sphere of radius 1 at (0, 0, -4), away from the ray");
    const std::optional<PrimitiveHit> missed = closest_hit(ray, list);
    INFO("closest_hit found " << text(missed));
    REQUIRE_FALSE(missed);
}

TEST_CASE("closest_hit: on a tie the primitive listed first wins", "[stage3]") {
    INFO(uses("closest_hit", "the intersect_* functions"));
    PrimitiveList list;
    const Triangle front{{-1, -1, -5}, {1, -1, -5}, {0, 1, -5}};
    list.triangles = {front, front};
    list.planes = {{{0, 0, -5}, {0, 0, 1}}};
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    INFO(text(ray) +
         "\ntwo copies of one triangle and a plane, all at t = 5: spheres, then "
         "triangles, then planes, each in list order, so triangle 0");
    const std::optional<PrimitiveHit> hit = closest_hit(ray, list);
    INFO("closest_hit found " << text(hit));
    REQUIRE(hit);
    REQUIRE(hit->kind == PrimitiveKind::triangle);
    REQUIRE(hit->index == 0);
}
