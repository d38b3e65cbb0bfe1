// Public tests for stage 3, the triangle tests. Every behaviour below must hold for each of the
// three lecture methods and for intersect_triangle, the one the renderer uses. Each method has its
// own test cases, named after it, so one method can be tested while the others are still stubs:
//   raystep_stage3_tests "intersect_triangle_cramer:*"
//
// Each check calls the method once, before its CHECKs: a stub ends the test case at its first
// call and is reported once. Where a test tries several rays, it stops at the first that fails,
// and a failure names the functions the method is built from: start with theirs.

#define GLM_ENABLE_EXPERIMENTAL
#include <algorithm>
#include <limits>
#include <optional>
#include <string>

#include <glm/gtx/intersect.hpp>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "base/testing/number_text.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/3_intersect/intersect.h"

using namespace raystep;
using raystep::testing::exact_text;
using raystep::testing::IsNear;
using raystep::testing::uses;

namespace {

using TriangleTest = std::optional<Hit> (*)(const Ray&, const Triangle&);

const double kInf = std::numeric_limits<double>::infinity();

// The right triangle (0,0,0) (1,0,0) (0,1,0) in the z = 0 plane, normal +z.
const Triangle kUnitTriangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

// A ray straight down the -z axis towards the point (x, y, 0), starting at z = 2.
Ray down_at(double x, double y) {
    return {{x, y, 2}, {0, 0, -1}};
}

// What a method is built from, for its failures: a bug there fails the method too.
std::string built_from(TriangleTest intersect) {
    if (intersect == intersect_triangle_projection) {
        return uses("intersect_triangle_projection", "stage 1's cross and dot");
    }
    if (intersect == intersect_triangle_halfspaces) {
        return uses("intersect_triangle_halfspaces", "stage 1's cross, dot, perpendicular_to");
    }
    if (intersect == intersect_triangle_cramer) {
        return uses("intersect_triangle_cramer", "stage 1's cross and dot");
    }
    return uses("intersect_triangle", "the method it calls");
}

// What a failed check prints: the ray and the triangle it was given, in full precision.
std::string inputs(const Ray& ray, const Triangle& triangle) {
    return "ray: origin " + exact_text(ray.origin) + ", direction " + exact_text(ray.direction) +
           ", t in [" + exact_text(ray.t_min) + ", " + exact_text(ray.t_max) +
           "]\ntriangle: " + exact_text(triangle.p0) + ", " + exact_text(triangle.p1) + ", " +
           exact_text(triangle.p2);
}

// Whether `intersect` reports a hit for `ray`, with the inputs in the failure message; a wrong
// answer ends the test case.
void check_hits(TriangleTest intersect, const Ray& ray, const Triangle& triangle, bool expected,
                const char* why) {
    INFO(built_from(intersect));
    INFO(why);
    INFO(inputs(ray, triangle));
    const bool hit = intersect(ray, triangle).has_value();
    REQUIRE(hit == expected);
}

void check_interior_hit(TriangleTest intersect) {
    INFO(built_from(intersect));
    const Ray ray = down_at(0.25, 0.5);
    INFO(
        "(0.25, 0.5, 0) = 0.25 p0 + 0.25 p1 + 0.5 p2, 2 below the origin: expected t = 2, "
        "beta = 0.25, gamma = 0.5, normal (0, 0, 1)");
    INFO(inputs(ray, kUnitTriangle));
    const std::optional<Hit> hit = intersect(ray, kUnitTriangle);
    REQUIRE(hit);
    CHECK(hit->t == Approx(2.0));
    CHECK(hit->beta == Approx(0.25));
    CHECK(hit->gamma == Approx(0.5));
    CHECK_THAT(hit->normal, IsNear(Vec3{0, 0, 1}, 1e-15));
}

void check_normal_from_behind(TriangleTest intersect) {
    INFO(built_from(intersect));
    const Triangle clockwise{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}};
    const Ray ray = down_at(0.2, 0.2);
    INFO(
        "(p1 - p0) x (p2 - p0) = (0, 0, -1), facing away from the ray: triangles are two-sided, "
        "and the normal is that cross product, not turned towards the ray");
    INFO(inputs(ray, clockwise));
    const std::optional<Hit> hit = intersect(ray, clockwise);
    REQUIRE(hit);
    CHECK_THAT(hit->normal, IsNear(Vec3{0, 0, -1}, 1e-15));
}

void check_outside_edges(TriangleTest intersect) {
    check_hits(intersect, down_at(0.5, -0.1), kUnitTriangle, false, "below the edge p0 p1");
    check_hits(intersect, down_at(-0.1, 0.5), kUnitTriangle, false, "left of the edge p2 p0");
    check_hits(intersect, down_at(0.6, 0.6), kUnitTriangle, false, "beyond the edge p1 p2");
    check_hits(intersect, down_at(2.0, 2.0), kUnitTriangle, false, "far outside");
}

void check_on_edges(TriangleTest intersect) {
    // Every coordinate here is exact in binary, so the edge tests see exactly 0.
    const char* closed = "on the boundary, which belongs to the triangle (exact in binary)";
    check_hits(intersect, down_at(0.5, 0.0), kUnitTriangle, true, closed);   // edge p0 p1
    check_hits(intersect, down_at(0.0, 0.25), kUnitTriangle, true, closed);  // edge p2 p0
    check_hits(intersect, down_at(0.5, 0.5), kUnitTriangle, true, closed);   // edge p1 p2
    check_hits(intersect, down_at(0.0, 0.0), kUnitTriangle, true, closed);   // vertex p0
    check_hits(intersect, down_at(1.0, 0.0), kUnitTriangle, true, closed);   // vertex p1
}

void check_t_range(TriangleTest intersect) {
    check_hits(intersect, {{0.2, 0.2, -1}, {0, 0, -1}}, kUnitTriangle, false,
               "the triangle is behind the origin (t = -1)");
    check_hits(intersect, {{0.2, 0.2, 2}, {0, 0, -1}, 0.0, 1.5}, kUnitTriangle, false,
               "the hit at t = 2 is beyond t_max");
    check_hits(intersect, {{0.2, 0.2, 2}, {0, 0, -1}, 2.5, kInf}, kUnitTriangle, false,
               "the hit at t = 2 is before t_min");
    check_hits(intersect, {{0.2, 0.2, 2}, {0, 0, -1}, 2.0, 2.0}, kUnitTriangle, true,
               "t = 2 with t_min = t_max = 2: the range is closed");
}

void check_parallel(TriangleTest intersect) {
    check_hits(intersect, {{-1, 0.2, 1}, {1, 0, 0}}, kUnitTriangle, false,
               "parallel to the triangle, above it");
    check_hits(intersect, {{-1, 0.2, 0}, {1, 0, 0}}, kUnitTriangle, false,
               "parallel to the triangle, in its plane");
}

void check_degenerate(TriangleTest intersect) {
    const Triangle collinear{{0, 0, 0}, {1, 1, 0}, {2, 2, 0}};
    const Triangle point{{1, 1, 0}, {1, 1, 0}, {1, 1, 0}};
    check_hits(intersect, down_at(1, 1), collinear, false, "three collinear vertices: no area");
    check_hits(intersect, down_at(1, 1), point, false, "three equal vertices: no area");
    check_hits(intersect, {{0.2, 0.2, 2}, {0, 0, 0}}, kUnitTriangle, false,
               "a zero direction goes nowhere");
}

void check_collinear_off_axes(TriangleTest intersect) {
    // Slivers case 258.
    const Triangle line{{-2, -2, 3}, {1, -2, 4}, {7, -2, 6}};
    const Ray ray{{4.5889181497847309, 1.4052998108618673, 6.6189080707000807},
                  {4.4443599190418146, -8.0381775442856807, -1.8765851199167081}};
    check_hits(intersect, ray, line, false,
               "the vertices lie on one line (steps (3,0,1) and (6,0,2)). Cramer's determinant "
               "is exactly 0 here, but a test that first transforms the vertices (the watertight "
               "test shears them along the ray) rounds them off the line, finds a tiny "
               "determinant, and reports a hit on a triangle with no area and no normal");
}

void check_agrees_with_glm(TriangleTest intersect) {
    INFO(built_from(intersect));
    // glm's Moller-Trumbore test as the independent answer. Away from the edges (where rounding
    // may decide either way) every method must give the same answer, t and barycentrics.
    int hits = 0;
    for (int k = 0; k < 5000; ++k) {
        PortableRandom random(31, static_cast<std::uint64_t>(k));  // case k, on every platform
        const Triangle tri{random.point(2.0), random.point(2.0), random.point(2.0)};
        const Vec3 origin = random.point(2.0) + Vec3(0, 0, 5);
        const Vec3 direction{random.uniform(-0.4, 0.4), random.uniform(-0.4, 0.4), -1.0};
        const Ray ray{origin, direction};
        glm::dvec2 barycentric(0.0);
        double t = 0.0;
        bool expected =
            glm::intersectRayTriangle(origin, direction, tri.p0, tri.p1, tri.p2, barycentric, t) &&
            t >= 0.0;
        if (expected) {
            const double alpha = 1.0 - barycentric.x - barycentric.y;
            if (std::min({alpha, barycentric.x, barycentric.y}) < 1e-6) continue;  // near an edge
            ++hits;
        }
        // glm leaves t and the barycentrics as they were when it misses: print them on a hit only.
        INFO("random ray " << k << ": glm says "
                           << (expected ? "a hit at t = " + exact_text(t) +
                                              ", beta = " + exact_text(barycentric.x) +
                                              ", gamma = " + exact_text(barycentric.y)
                                        : std::string("a miss")));
        INFO(inputs(ray, tri));
        const std::optional<Hit> hit = intersect(ray, tri);
        REQUIRE(hit.has_value() == expected);
        if (hit) {
            REQUIRE(hit->t == Approx(t).epsilon(1e-9));
            REQUIRE(hit->beta == Approx(barycentric.x).epsilon(1e-7));
            REQUIRE(hit->gamma == Approx(barycentric.y).epsilon(1e-7));
        }
    }
    CHECK(hits > 150);  // the loop really compared hits, not just misses
}

}  // namespace

// Method 1: projection onto a coordinate plane.

TEST_CASE(
    "intersect_triangle_projection: a ray through the interior hits with t and "
    "barycentrics",
    "[stage3]") {
    check_interior_hit(intersect_triangle_projection);
}
TEST_CASE(
    "intersect_triangle_projection: the normal is (p1 - p0) x (p2 - p0), even seen from "
    "behind",
    "[stage3]") {
    check_normal_from_behind(intersect_triangle_projection);
}
TEST_CASE("intersect_triangle_projection: points outside each edge miss", "[stage3]") {
    check_outside_edges(intersect_triangle_projection);
}
TEST_CASE("intersect_triangle_projection: points on an edge or a vertex belong to the triangle",
          "[stage3]") {
    check_on_edges(intersect_triangle_projection);
}
TEST_CASE("intersect_triangle_projection: hits outside [t_min, t_max] are misses", "[stage3]") {
    check_t_range(intersect_triangle_projection);
}
TEST_CASE("intersect_triangle_projection: a ray parallel to the triangle misses", "[stage3]") {
    check_parallel(intersect_triangle_projection);
}
TEST_CASE("intersect_triangle_projection: a degenerate triangle or a zero direction misses",
          "[stage3]") {
    check_degenerate(intersect_triangle_projection);
}
TEST_CASE("intersect_triangle_projection: a collinear triangle off the axes is a miss",
          "[stage3]") {
    check_collinear_off_axes(intersect_triangle_projection);
}
TEST_CASE("intersect_triangle_projection: agrees with glm::intersectRayTriangle on random rays",
          "[stage3]") {
    check_agrees_with_glm(intersect_triangle_projection);
}

// Method 2: the three edges' half-spaces.

TEST_CASE(
    "intersect_triangle_halfspaces: a ray through the interior hits with t and "
    "barycentrics",
    "[stage3]") {
    check_interior_hit(intersect_triangle_halfspaces);
}
TEST_CASE(
    "intersect_triangle_halfspaces: the normal is (p1 - p0) x (p2 - p0), even seen from "
    "behind",
    "[stage3]") {
    check_normal_from_behind(intersect_triangle_halfspaces);
}
TEST_CASE("intersect_triangle_halfspaces: points outside each edge miss", "[stage3]") {
    check_outside_edges(intersect_triangle_halfspaces);
}
TEST_CASE("intersect_triangle_halfspaces: points on an edge or a vertex belong to the triangle",
          "[stage3]") {
    check_on_edges(intersect_triangle_halfspaces);
}
TEST_CASE("intersect_triangle_halfspaces: hits outside [t_min, t_max] are misses", "[stage3]") {
    check_t_range(intersect_triangle_halfspaces);
}
TEST_CASE("intersect_triangle_halfspaces: a ray parallel to the triangle misses", "[stage3]") {
    check_parallel(intersect_triangle_halfspaces);
}
TEST_CASE("intersect_triangle_halfspaces: a degenerate triangle or a zero direction misses",
          "[stage3]") {
    check_degenerate(intersect_triangle_halfspaces);
}
TEST_CASE("intersect_triangle_halfspaces: a collinear triangle off the axes is a miss",
          "[stage3]") {
    check_collinear_off_axes(intersect_triangle_halfspaces);
}
TEST_CASE("intersect_triangle_halfspaces: agrees with glm::intersectRayTriangle on random rays",
          "[stage3]") {
    check_agrees_with_glm(intersect_triangle_halfspaces);
}

// Method 3: Cramer's rule.

TEST_CASE("intersect_triangle_cramer: a ray through the interior hits with t and barycentrics",
          "[stage3]") {
    check_interior_hit(intersect_triangle_cramer);
}
TEST_CASE("intersect_triangle_cramer: the normal is (p1 - p0) x (p2 - p0), even seen from behind",
          "[stage3]") {
    check_normal_from_behind(intersect_triangle_cramer);
}
TEST_CASE("intersect_triangle_cramer: points outside each edge miss", "[stage3]") {
    check_outside_edges(intersect_triangle_cramer);
}
TEST_CASE("intersect_triangle_cramer: points on an edge or a vertex belong to the triangle",
          "[stage3]") {
    check_on_edges(intersect_triangle_cramer);
}
TEST_CASE("intersect_triangle_cramer: hits outside [t_min, t_max] are misses", "[stage3]") {
    check_t_range(intersect_triangle_cramer);
}
TEST_CASE("intersect_triangle_cramer: a ray parallel to the triangle misses", "[stage3]") {
    check_parallel(intersect_triangle_cramer);
}
TEST_CASE("intersect_triangle_cramer: a degenerate triangle or a zero direction misses",
          "[stage3]") {
    check_degenerate(intersect_triangle_cramer);
}
TEST_CASE("intersect_triangle_cramer: a collinear triangle off the axes is a miss", "[stage3]") {
    check_collinear_off_axes(intersect_triangle_cramer);
}
TEST_CASE("intersect_triangle_cramer: agrees with glm::intersectRayTriangle on random rays",
          "[stage3]") {
    check_agrees_with_glm(intersect_triangle_cramer);
}

// The renderer's choice, in triangle.cpp: whichever method it calls must pass them all.

TEST_CASE("intersect_triangle: a ray through the interior hits with t and barycentrics",
          "[stage3]") {
    check_interior_hit(intersect_triangle);
}
TEST_CASE("intersect_triangle: the normal is (p1 - p0) x (p2 - p0), even seen from behind",
          "[stage3]") {
    check_normal_from_behind(intersect_triangle);
}
TEST_CASE("intersect_triangle: points outside each edge miss", "[stage3]") {
    check_outside_edges(intersect_triangle);
}
TEST_CASE("intersect_triangle: points on an edge or a vertex belong to the triangle", "[stage3]") {
    check_on_edges(intersect_triangle);
}
TEST_CASE("intersect_triangle: hits outside [t_min, t_max] are misses", "[stage3]") {
    check_t_range(intersect_triangle);
}
TEST_CASE("intersect_triangle: a ray parallel to the triangle misses", "[stage3]") {
    check_parallel(intersect_triangle);
}
TEST_CASE("intersect_triangle: a degenerate triangle or a zero direction misses", "[stage3]") {
    check_degenerate(intersect_triangle);
}
TEST_CASE("intersect_triangle: a collinear triangle off the axes is a miss", "[stage3]") {
    check_collinear_off_axes(intersect_triangle);
}
TEST_CASE("intersect_triangle: agrees with glm::intersectRayTriangle on random rays", "[stage3]") {
    check_agrees_with_glm(intersect_triangle);
}
