// Public tests for stage 3. Run them with `ctest --test-dir build/release -L stage3`.

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <glm/geometric.hpp>

#include "base/testing/catch.h"
#include "base/testing/vec3_matchers.h"
#include "stages/3_intersect/intersect.h"

using namespace raystep;
using raystep::testing::IsNear;

namespace {

using TriangleTest = std::optional<Hit> (*)(const Ray&, const Triangle&);

struct NamedTest {
    const char* name;
    TriangleTest intersect;
};

// The three lecture methods and the one the renderer uses: every triangle behaviour below must
// hold for each.
const NamedTest kTriangleTests[] = {
    {"intersect_triangle_projection", intersect_triangle_projection},
    {"intersect_triangle_halfspaces", intersect_triangle_halfspaces},
    {"intersect_triangle_cramer", intersect_triangle_cramer},
    {"intersect_triangle", intersect_triangle},
};

const double kInf = std::numeric_limits<double>::infinity();

// The right triangle (0,0,0) (1,0,0) (0,1,0) in the z = 0 plane, normal +z.
const Triangle kUnitTriangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

// A ray straight down the -z axis towards the point (x, y, 0), starting at z = 2.
Ray down_at(double x, double y) {
    return {{x, y, 2}, {0, 0, -1}};
}

}  // namespace

TEST_CASE("intersect_plane: hits the floor at the distance down to it", "[stage3]") {
    const Plane floor{{0, -1, 0}, {0, 2, 0}};  // y = -1, normal of length 2
    const std::optional<Hit> hit = intersect_plane({{0, 3, 0}, {0, -1, 0}}, floor);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK_THAT(hit->normal, IsNear(Vec3{0, 1, 0}, 1e-15));  // unit length, as given
}

TEST_CASE("intersect_plane: a ray parallel to the plane misses", "[stage3]") {
    const Plane floor{{0, 0, 0}, {0, 1, 0}};
    CHECK_FALSE(intersect_plane({{0, 1, 0}, {1, 0, 0}}, floor));
    CHECK_FALSE(intersect_plane({{0, 0, 0}, {1, 0, 0}}, floor));  // even lying in it
}

TEST_CASE("intersect_plane: a plane behind the ray or beyond t_max misses", "[stage3]") {
    const Plane floor{{0, 0, 0}, {0, 1, 0}};
    CHECK_FALSE(intersect_plane({{0, 1, 0}, {0, 1, 0}}, floor));             // behind
    CHECK_FALSE(intersect_plane({{0, 1, 0}, {0, -1, 0}, 0.0, 0.5}, floor));  // too far
    CHECK(intersect_plane({{0, 1, 0}, {0, -1, 0}, 0.0, 1.0}, floor));        // t_max included
}

TEST_CASE("intersect_plane: a zero direction misses", "[stage3]") {
    CHECK_FALSE(intersect_plane({{0, 1, 0}, {0, 0, 0}}, {{0, 0, 0}, {0, 1, 0}}));
}

TEST_CASE("intersect_triangle_*: a ray through the interior hits with t and barycentrics",
          "[stage3]") {
    for (const NamedTest& method : kTriangleTests) {
        CAPTURE(method.name);
        // The point (0.25, 0.5, 0) = 0.25 p0 + 0.25 p1 + 0.5 p2.
        const std::optional<Hit> hit = method.intersect(down_at(0.25, 0.5), kUnitTriangle);
        REQUIRE(hit);
        CHECK(hit->t == Approx(2.0));
        CHECK(hit->beta == Approx(0.25));
        CHECK(hit->gamma == Approx(0.5));
        CHECK_THAT(hit->normal, IsNear(Vec3{0, 0, 1}, 1e-15));
    }
}

TEST_CASE("intersect_triangle_*: the normal is (p1 - p0) x (p2 - p0), even seen from behind",
          "[stage3]") {
    const Triangle clockwise{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}};  // normal -z
    for (const NamedTest& method : kTriangleTests) {
        CAPTURE(method.name);
        const std::optional<Hit> hit = method.intersect(down_at(0.2, 0.2), clockwise);
        REQUIRE(hit);  // triangles are two-sided
        CHECK_THAT(hit->normal, IsNear(Vec3{0, 0, -1}, 1e-15));
    }
}

TEST_CASE("intersect_triangle_*: points outside each edge miss", "[stage3]") {
    for (const NamedTest& method : kTriangleTests) {
        CAPTURE(method.name);
        CHECK_FALSE(method.intersect(down_at(0.5, -0.1), kUnitTriangle));  // below p0 p1
        CHECK_FALSE(method.intersect(down_at(-0.1, 0.5), kUnitTriangle));  // left of p2 p0
        CHECK_FALSE(method.intersect(down_at(0.6, 0.6), kUnitTriangle));   // beyond p1 p2
        CHECK_FALSE(method.intersect(down_at(2.0, 2.0), kUnitTriangle));
    }
}

TEST_CASE("intersect_triangle_*: points on an edge or a vertex belong to the triangle",
          "[stage3]") {
    // Every coordinate here is exact in binary, so the edge tests see exactly 0.
    for (const NamedTest& method : kTriangleTests) {
        CAPTURE(method.name);
        CHECK(method.intersect(down_at(0.5, 0.0), kUnitTriangle));   // edge p0 p1
        CHECK(method.intersect(down_at(0.0, 0.25), kUnitTriangle));  // edge p2 p0
        CHECK(method.intersect(down_at(0.5, 0.5), kUnitTriangle));   // edge p1 p2
        CHECK(method.intersect(down_at(0.0, 0.0), kUnitTriangle));   // vertex p0
        CHECK(method.intersect(down_at(1.0, 0.0), kUnitTriangle));   // vertex p1
    }
}

TEST_CASE("intersect_triangle_*: hits outside [t_min, t_max] are misses", "[stage3]") {
    for (const NamedTest& method : kTriangleTests) {
        CAPTURE(method.name);
        CHECK_FALSE(method.intersect({{0.2, 0.2, -1}, {0, 0, -1}}, kUnitTriangle));  // behind
        CHECK_FALSE(method.intersect({{0.2, 0.2, 2}, {0, 0, -1}, 0.0, 1.5}, kUnitTriangle));
        CHECK_FALSE(method.intersect({{0.2, 0.2, 2}, {0, 0, -1}, 2.5, kInf}, kUnitTriangle));
        CHECK(method.intersect({{0.2, 0.2, 2}, {0, 0, -1}, 2.0, 2.0}, kUnitTriangle));
    }
}

TEST_CASE("intersect_triangle_*: a ray parallel to the triangle misses", "[stage3]") {
    for (const NamedTest& method : kTriangleTests) {
        CAPTURE(method.name);
        CHECK_FALSE(method.intersect({{-1, 0.2, 1}, {1, 0, 0}}, kUnitTriangle));
        CHECK_FALSE(method.intersect({{-1, 0.2, 0}, {1, 0, 0}}, kUnitTriangle));  // in its plane
    }
}

TEST_CASE("intersect_triangle_*: a degenerate triangle or a zero direction misses, never NaN",
          "[stage3]") {
    const Triangle collinear{{0, 0, 0}, {1, 1, 0}, {2, 2, 0}};
    const Triangle point{{1, 1, 0}, {1, 1, 0}, {1, 1, 0}};
    for (const NamedTest& method : kTriangleTests) {
        CAPTURE(method.name);
        CHECK_FALSE(method.intersect(down_at(1, 1), collinear));
        CHECK_FALSE(method.intersect(down_at(1, 1), point));
        CHECK_FALSE(method.intersect({{0.2, 0.2, 2}, {0, 0, 0}}, kUnitTriangle));
    }
}

TEST_CASE(
    "intersect_triangle_*: a collinear triangle off the axes is a miss, even when rounding leaves "
    "a tiny determinant",
    "[stage3]") {
    // (-2,-2,3), (1,-2,4), (7,-2,6) lie on one line (steps (3,0,1) and (6,0,2)). Cramer's
    // determinant is exactly 0 here, but a test that first transforms the vertices (the
    // watertight test shears them along the ray) rounds them off the line, finds a tiny
    // determinant, and reports a hit on a triangle with no area and no normal (slivers case 258).
    const Triangle line{{-2, -2, 3}, {1, -2, 4}, {7, -2, 6}};
    const Ray ray{{4.5889181497847309, 1.4052998108618673, 6.6189080707000807},
                  {4.4443599190418146, -8.0381775442856807, -1.8765851199167081}};
    for (const NamedTest& method : kTriangleTests) {
        CAPTURE(method.name);
        CHECK_FALSE(method.intersect(ray, line));
    }
}

TEST_CASE("intersect_triangle_*: the three methods agree on random rays", "[stage3]") {
    // Away from the edges (where rounding may decide either way) every method must give the same
    // answer, the same t and the same barycentrics.
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    int hits = 0;
    for (int k = 0; k < 5000; ++k) {
        const Triangle tri{
            {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
        const Ray ray{{u(rng), u(rng), u(rng) + 5.0}, {u(rng) * 0.2, u(rng) * 0.2, -1.0}};
        const std::optional<Hit> expected = intersect_triangle_cramer(ray, tri);
        if (expected) {
            const double alpha = 1.0 - expected->beta - expected->gamma;
            if (std::min({alpha, expected->beta, expected->gamma}) < 1e-6)
                continue;  // near an edge
            ++hits;
        }
        for (const NamedTest& method : kTriangleTests) {
            CAPTURE(k, method.name);
            const std::optional<Hit> hit = method.intersect(ray, tri);
            REQUIRE(hit.has_value() == expected.has_value());
            if (hit) {
                CHECK(hit->t == Approx(expected->t).epsilon(1e-9));
                CHECK(hit->beta == Approx(expected->beta).epsilon(1e-7));
                CHECK(hit->gamma == Approx(expected->gamma).epsilon(1e-7));
            }
        }
    }
    CHECK(hits > 150);  // the loop really compared hits, not just misses
}

TEST_CASE("intersect_sphere: a ray at the centre hits the near side", "[stage3]") {
    const std::optional<Hit> hit = intersect_sphere({{0, 0, 5}, {0, 0, -1}}, {{0, 0, 0}, 1.0});
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK_THAT(hit->normal, IsNear(Vec3{0, 0, 1}, 1e-15));
}

TEST_CASE("intersect_sphere: t is in units of the direction's length", "[stage3]") {
    const std::optional<Hit> hit = intersect_sphere({{0, 0, 5}, {0, 0, -2}}, {{0, 0, 0}, 1.0});
    REQUIRE(hit);
    CHECK(hit->t == Approx(2.0));
}

TEST_CASE("intersect_sphere: from inside, the ray hits the far side", "[stage3]") {
    const std::optional<Hit> hit = intersect_sphere({{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, 2.0});
    REQUIRE(hit);
    CHECK(hit->t == Approx(2.0));
    CHECK_THAT(hit->normal, IsNear(Vec3{1, 0, 0}, 1e-15));  // outward, not towards the ray
}

TEST_CASE("intersect_sphere: a near root before t_min gives way to the far root", "[stage3]") {
    const std::optional<Hit> hit =
        intersect_sphere({{0, 0, 5}, {0, 0, -1}, 4.5, kInf}, {{0, 0, 0}, 1.0});
    REQUIRE(hit);
    CHECK(hit->t == Approx(6.0));
}

TEST_CASE("intersect_sphere: misses a sphere beside the ray or behind it", "[stage3]") {
    CHECK_FALSE(intersect_sphere({{0, 2, 5}, {0, 0, -1}}, {{0, 0, 0}, 1.0}));
    CHECK_FALSE(intersect_sphere({{0, 0, 5}, {0, 0, 1}}, {{0, 0, 0}, 1.0}));
}

TEST_CASE("intersect_sphere: a tangent ray touches the sphere once", "[stage3]") {
    const std::optional<Hit> hit = intersect_sphere({{0, 1, 5}, {0, 0, -1}}, {{0, 0, 0}, 1.0});
    REQUIRE(hit);
    CHECK(hit->t == Approx(5.0));
    CHECK_THAT(hit->normal, IsNear(Vec3{0, 1, 0}, 1e-7));
}

TEST_CASE("intersect_sphere: a zero radius or a zero direction misses, never NaN", "[stage3]") {
    CHECK_FALSE(intersect_sphere({{0, 0, 5}, {0, 0, -1}}, {{0, 0, 0}, 0.0}));
    CHECK_FALSE(intersect_sphere({{0, 0, 5}, {0, 0, 0}}, {{0, 0, 0}, 1.0}));
}

TEST_CASE("intersect_sphere: a ray starting just outside a large sphere hits it at a tiny t",
          "[stage3]") {
    // Radius 5e7, origin 1 unit beside the top of the sphere, going down: the near root is
    // t = c / q = 1 / (5e7 + sqrt(2.5e15 - 1)) = 1e-8, and every intermediate here is exact. The
    // textbook -b - sqrt(b^2 - 4ac) subtracts two numbers near 1e8 that differ by 2e-8 and gets
    // 7.45e-9, 25% short; the stable form q = -(b + sign(b) sqrt(...)) has nothing to cancel.
    const Sphere large{{0, 0, 0}, 5e7};
    const std::optional<Hit> hit = intersect_sphere({{1, 5e7, 0}, {0, -1, 0}}, large);
    REQUIRE(hit);
    CHECK(hit->t == Approx(1e-8).epsilon(1e-12));
    CHECK_THAT(hit->normal, IsNear(Vec3(2e-8, 1, 0), 1e-12));
}

TEST_CASE("intersect_sphere: a small sphere far away, hit to the nanometre", "[stage3]") {
    // A 1 mm sphere 100 km away: b^2 and a c are both near 1e10, and b^2 - a c keeps only a few
    // of its digits, a fraction of a millimetre. Written as a (r^2 - |f - (b / a) D|^2), r^2
    // minus the squared distance from the centre to the ray's line, it has nothing to cancel.
    // Exactly: 1e5 - 1e-3 = 99999.999, and 1e5 - sqrt(r^2 - 0.6e-3^2) = 99999.9992.
    const Sphere sphere{{1e5, 0, 0}, 1e-3};
    const std::optional<Hit> hit = intersect_sphere({{0, 0, 0}, {1, 0, 0}}, sphere);
    REQUIRE(hit);
    CHECK(hit->t == Approx(99999.999).margin(1e-9));
    const std::optional<Hit> offset = intersect_sphere({{0, 0.6e-3, 0}, {1, 0, 0}}, sphere);
    REQUIRE(offset);
    CHECK(offset->t == Approx(99999.9992).margin(1e-9));
    CHECK_THAT(offset->normal, IsNear(Vec3(-0.8, 0.6, 0), 1e-5));
    // A line 1.00001 r from the centre misses; b^2 - a c cannot tell it from a hit.
    CHECK_FALSE(intersect_sphere({{0, 1.00001e-3, 0}, {1, 0, 0}}, sphere));
}

TEST_CASE("intersect_sphere: a huge sphere is hit where it should be", "[stage3]") {
    // The ground as a sphere of radius 1e6 centred 1e6 below the origin.
    const Sphere ground{{0, -1e6, 0}, 1e6};
    const std::optional<Hit> hit = intersect_sphere({{0, 10, 0}, {0, -1, 0}}, ground);
    REQUIRE(hit);
    CHECK(hit->t == Approx(10.0).epsilon(1e-9));
    CHECK_THAT(hit->normal, IsNear(Vec3{0, 1, 0}, 1e-9));
}

TEST_CASE("closest_hit: returns the nearest of several primitives", "[stage3]") {
    PrimitiveList list;
    list.spheres = {{{0, 0, -10}, 1.0}, {{0, 0, -4}, 1.0}};
    list.triangles = {{{-1, -1, -6}, {1, -1, -6}, {0, 1, -6}}};
    list.planes = {{{0, 0, -20}, {0, 0, 1}}};
    const std::optional<PrimitiveHit> hit = closest_hit({{0, 0, 0}, {0, 0, -1}}, list);
    REQUIRE(hit);
    CHECK(hit->kind == PrimitiveKind::sphere);
    CHECK(hit->index == 1);
    CHECK(hit->hit.t == Approx(3.0));
}

TEST_CASE("closest_hit: a triangle or a plane can be nearest too", "[stage3]") {
    PrimitiveList list;
    list.spheres = {{{0, 0, -10}, 1.0}};
    list.triangles = {{{-1, -1, -6}, {1, -1, -6}, {0, 1, -6}},
                      {{-1, -1, -5}, {1, -1, -5}, {0, 1, -5}}};
    list.planes = {{{0, 0, -20}, {0, 0, 1}}};
    std::optional<PrimitiveHit> hit = closest_hit({{0, 0, 0}, {0, 0, -1}}, list);
    REQUIRE(hit);
    CHECK(hit->kind == PrimitiveKind::triangle);
    CHECK(hit->index == 1);
    CHECK(hit->hit.t == Approx(5.0));

    list.planes.push_back({{0, 0, -2}, {0, 0, 1}});
    hit = closest_hit({{0, 0, 0}, {0, 0, -1}}, list);
    REQUIRE(hit);
    CHECK(hit->kind == PrimitiveKind::plane);
    CHECK(hit->index == 1);
}

TEST_CASE("closest_hit: respects the ray's [t_min, t_max]", "[stage3]") {
    PrimitiveList list;
    list.spheres = {{{0, 0, -4}, 1.0}};
    list.planes = {{{0, 0, -8}, {0, 0, 1}}};
    // The sphere's near side (t = 3) is before t_min: its far side (t = 5) is the closest hit.
    std::optional<PrimitiveHit> hit = closest_hit({{0, 0, 0}, {0, 0, -1}, 4.0, kInf}, list);
    REQUIRE(hit);
    CHECK(hit->hit.t == Approx(5.0));
    CHECK_FALSE(closest_hit({{0, 0, 0}, {0, 0, -1}, 0.0, 2.0}, list));
}

TEST_CASE("closest_hit: an empty list or a ray that misses everything gives no hit", "[stage3]") {
    CHECK_FALSE(closest_hit({{0, 0, 0}, {0, 0, -1}}, PrimitiveList{}));
    PrimitiveList list;
    list.spheres = {{{0, 0, -4}, 1.0}};
    CHECK_FALSE(closest_hit({{0, 0, 0}, {0, 1, 0}}, list));
}

TEST_CASE("closest_hit: on a tie the primitive listed first wins", "[stage3]") {
    PrimitiveList list;
    const Triangle front{{-1, -1, -5}, {1, -1, -5}, {0, 1, -5}};
    list.triangles = {front, front};
    list.planes = {{{0, 0, -5}, {0, 0, 1}}};
    const std::optional<PrimitiveHit> hit = closest_hit({{0, 0, 0}, {0, 0, -1}}, list);
    REQUIRE(hit);
    CHECK(hit->kind == PrimitiveKind::triangle);
    CHECK(hit->index == 0);
}
