// Tests of the exact oracle against answers computed by hand or, where the numbers are not
// round, independently in exact rational arithmetic (Python's fractions.Fraction and decimal at
// 200 digits; the values are literals here).

#include <cmath>

#include <gmpxx.h>

#include "base/testing/catch.h"
#include "base/testing/special_values.h"
#include "base/testing/vec3_matchers.h"
#include "grading/3_intersect/exact_intersection.h"
#include "grading/3_intersect/nearest_double.h"

using namespace raystep;
using raystep::testing::IsNear;

namespace {

using raystep::testing::kInf;

// The right triangle (0,0,0) (1,0,0) (0,1,0) in the z = 0 plane.
const Triangle kUnitTriangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

Ray down_at(double x, double y) {
    return {{x, y, 2}, {0, 0, -1}};
}

double nearest(const char* rational) {
    const mpq_class q(rational);
    return nearest_double(q.get_mpq_t());
}

double root(const char* a, const char* b, const char* c, bool smaller) {
    const mpq_class qa(a), qb(b), qc(c);
    const mpq_class disc = qb * qb - qa * qc;
    return nearest_double_of_root(qa.get_mpq_t(), qb.get_mpq_t(), qc.get_mpq_t(), disc.get_mpq_t(),
                                  smaller);
}

}  // namespace

TEST_CASE("nearest_double: rounds rationals to nearest, ties to even", "[oracle]") {
    CHECK(nearest("1/3") == 0x1.5555555555555p-2);
    CHECK(nearest("1/10") == 0.1);
    // 1 + 2^-53 is halfway between 1 and the next double: the tie goes to the even one, 1.
    CHECK(nearest("9007199254740993/9007199254740992") == 1.0);
    // 1 + 3 * 2^-53 is halfway between 1 + 2^-52 and 1 + 2^-51: to the even one, 1 + 2^-51.
    CHECK(nearest("9007199254740995/9007199254740992") == 1.0 + 0x1p-51);
    CHECK(nearest("-7/2") == -3.5);
}

TEST_CASE("nearest_double: subnormals and overflow round as IEEE doubles do", "[oracle]") {
    // 2^-1074, the smallest subnormal, is exact; 0.75 of it rounds up to it, 0.25 of it to 0.
    const mpq_class smallest = mpq_class(1) / (mpq_class(mpz_class(1) << 1074));
    CHECK(nearest_double(smallest.get_mpq_t()) == 0x1p-1074);
    const mpq_class three_quarters = smallest * mpq_class(3, 4);
    CHECK(nearest_double(three_quarters.get_mpq_t()) == 0x1p-1074);
    const mpq_class quarter = smallest / 4;
    CHECK(nearest_double(quarter.get_mpq_t()) == 0.0);
    const mpq_class huge = mpq_class(mpz_class(1) << 1100);
    CHECK(nearest_double(huge.get_mpq_t()) == kInf);
}

TEST_CASE("nearest_double_of_root: irrational roots at rising precision, rational ones exactly",
          "[oracle]") {
    // t^2 - 2 = 0: a = 1, b = 0, c = -2.
    CHECK(root("1", "0", "-2", false) == 1.4142135623730951);
    CHECK(root("1", "0", "-2", true) == -1.4142135623730951);
    // t^2 - 6 t + 5 = 0 (b = -3): roots 1 and 5, exactly.
    CHECK(root("1", "-3", "5", true) == 1.0);
    CHECK(root("1", "-3", "5", false) == 5.0);
    // A root below 1e-8 next to one near 1e8: t^2 - 2 5e7 t + 1 = 0, where the textbook formula
    // cancels; smaller root 1 / (5e7 + sqrt(2.5e15 - 1)) = 1e-8 to 17 digits.
    CHECK(root("1", "-50000000", "1", true) == 1e-8);
}

TEST_CASE("expect_triangle: a ray through the interior hits, away from any boundary", "[oracle]") {
    const Expectation e = expect_triangle(down_at(0.25, 0.5), kUnitTriangle);
    CHECK(e.hit);
    CHECK_FALSE(e.near_boundary);
    CHECK(e.t == 2.0);
    CHECK(e.beta == 0.25);
    CHECK(e.gamma == 0.5);
    CHECK_THAT(e.normal, IsNear(Vec3(0, 0, 1), 1e-15));
    CHECK(e.t_tolerance > 0.0);
    CHECK(e.t_tolerance < 1e-12);  // the budget at this scale is about 1e-14
}

TEST_CASE(
    "expect_triangle: t and barycentrics are the exact values rounded, not double arithmetic's",
    "[oracle]") {
    // Aimed at 0.3 p0 + 0.3 p1 + 0.4 p2 from 1 unit of t away. Exactly, t = 1; the double
    // expression (p0 - A) . N / (D . N) gives 0.9999999999999998.
    const Triangle tri{{0.492, 0.967, 1.181}, {1.77, 0.96, 1.689}, {-1.884, -0.138, 1.773}};
    const Ray ray{{0.298, 0.802, 4.226}, {-0.373, -0.27910000000000007, -2.6558}};
    const Expectation e = expect_triangle(ray, tri);
    CHECK(e.hit);
    CHECK(e.t == 1.0);
    CHECK(e.beta == 0.29999999999999993);
    CHECK(e.gamma == 0.39999999999999997);

    // And the other way: exactly 0.9999999999999999 where double arithmetic gives 1.
    const Triangle other{{0.47, -1.493, -1.993}, {1.486, -1.162, -1.138}, {1.93, 1.49, -0.843}};
    const Ray other_ray{{0.923, 0.078, 5.356},
                        {0.43579999999999997, -0.27849999999999997, -6.6325}};
    CHECK(expect_triangle(other_ray, other).t == 0.9999999999999999);
}

TEST_CASE("expect_triangle: points on an edge or a vertex hit, near the boundary", "[oracle]") {
    for (const Ray& ray :
         {down_at(0.5, 0.0), down_at(0.0, 0.5), down_at(0.5, 0.5), down_at(0, 0)}) {
        CAPTURE(ray.origin.x, ray.origin.y);
        const Expectation e = expect_triangle(ray, kUnitTriangle);
        CHECK(e.hit);
        CHECK(e.near_boundary);
    }
    // (1, 2) lies on the edge x + y = 3 of this larger triangle.
    const Expectation e = expect_triangle(down_at(1, 2), {{0, 0, 0}, {3, 0, 0}, {0, 3, 0}});
    CHECK(e.hit);
    CHECK(e.near_boundary);
}

TEST_CASE("expect_triangle: a clear miss is a miss away from any boundary", "[oracle]") {
    const Expectation e = expect_triangle(down_at(0.5, -1e-3), kUnitTriangle);
    CHECK_FALSE(e.hit);
    CHECK_FALSE(e.near_boundary);
    CHECK(std::isnan(e.t));
}

TEST_CASE("expect_triangle: a miss within rounding of an edge may go either way", "[oracle]") {
    const Expectation e = expect_triangle(down_at(0.5, -1e-17), kUnitTriangle);
    CHECK_FALSE(e.hit);
    CHECK(e.near_boundary);
    CHECK(e.t == 2.0);  // where a nearby ray would hit
}

TEST_CASE("expect_triangle: degenerate triangles and zero directions miss, by the contract",
          "[oracle]") {
    const Expectation collinear = expect_triangle(down_at(1, 1), {{0, 0, 0}, {1, 1, 0}, {2, 2, 0}});
    CHECK_FALSE(collinear.hit);
    CHECK_FALSE(collinear.near_boundary);
    const Expectation zero = expect_triangle({{0.2, 0.2, 2}, {0, 0, 0}}, kUnitTriangle);
    CHECK_FALSE(zero.hit);
    CHECK_FALSE(zero.near_boundary);
}

TEST_CASE("expect_triangle: a ray in the triangle's plane misses, near the boundary", "[oracle]") {
    const Expectation e = expect_triangle({{-1, 0.2, 0}, {1, 0, 0}}, kUnitTriangle);
    CHECK_FALSE(e.hit);
    CHECK(e.near_boundary);
    CHECK(std::isnan(e.t));
}

TEST_CASE("expect_triangle: t_min and t_max cut exactly, with rounding near them", "[oracle]") {
    CHECK(expect_triangle({{0.2, 0.2, 2}, {0, 0, -1}, 0.0, 2.0}, kUnitTriangle).hit);
    const Expectation short_ray =
        expect_triangle({{0.2, 0.2, 2}, {0, 0, -1}, 0.0, 1.5}, kUnitTriangle);
    CHECK_FALSE(short_ray.hit);
    CHECK_FALSE(short_ray.near_boundary);
    const Expectation just_short =
        expect_triangle({{0.2, 0.2, 2}, {0, 0, -1}, 0.0, std::nextafter(2.0, 0.0)}, kUnitTriangle);
    CHECK_FALSE(just_short.hit);
    CHECK(just_short.near_boundary);
}

TEST_CASE("expect_sphere: hits the near side of a sphere ahead", "[oracle]") {
    const Expectation e = expect_sphere({{0, 0, 5}, {0, 0, -1}}, {{0, 0, 0}, 1.0});
    CHECK(e.hit);
    CHECK_FALSE(e.near_boundary);
    CHECK(e.t == 4.0);
    CHECK_THAT(e.normal, IsNear(Vec3(0, 0, 1), 1e-15));
    CHECK(std::isnan(e.t_alternative));
}

TEST_CASE("expect_sphere: from inside, the far side", "[oracle]") {
    const Expectation e = expect_sphere({{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, 2.0});
    CHECK(e.hit);
    CHECK(e.t == 2.0);
    CHECK_THAT(e.normal, IsNear(Vec3(1, 0, 0), 1e-15));
}

TEST_CASE("expect_sphere: a ray starting on the surface may see t = 0 or the far side",
          "[oracle]") {
    // Roots 0 and 2: exactly, t = 0 is in [0, inf); after rounding a test may put it just below.
    const Expectation e = expect_sphere({{0, 0, 1}, {0, 0, -1}}, {{0, 0, 0}, 1.0});
    CHECK(e.hit);
    CHECK_FALSE(e.near_boundary);  // a hit either way
    CHECK(e.t == 0.0);
    CHECK(e.t_alternative == 2.0);
    CHECK_THAT(e.normal_alternative, IsNear(Vec3(0, 0, -1), 1e-15));
}

TEST_CASE("expect_sphere: a tangent ray hits exactly, near the boundary", "[oracle]") {
    const Expectation e = expect_sphere({{0, 1, 5}, {0, 0, -1}}, {{0, 0, 0}, 1.0});
    CHECK(e.hit);
    CHECK(e.near_boundary);
    CHECK(e.t == 5.0);
    // Just outside by less than the rounding budget: a miss that may go either way.
    const Expectation outside = expect_sphere({{0, 1 + 1e-15, 5}, {0, 0, -1}}, {{0, 0, 0}, 1.0});
    CHECK_FALSE(outside.hit);
    CHECK(outside.near_boundary);
    // Clearly outside: a miss.
    const Expectation clear = expect_sphere({{0, 1.001, 5}, {0, 0, -1}}, {{0, 0, 0}, 1.0});
    CHECK_FALSE(clear.hit);
    CHECK_FALSE(clear.near_boundary);
}

TEST_CASE("expect_sphere: the tiny near root beside a large sphere, exactly", "[oracle]") {
    const Expectation e = expect_sphere({{1, 5e7, 0}, {0, -1, 0}}, {{0, 0, 0}, 5e7});
    CHECK(e.hit);
    CHECK(e.t == 1e-8);
}

TEST_CASE("expect_sphere: a 1 mm sphere 100 km away, where the textbook form is off", "[oracle]") {
    // Exactly 1e5 - 1e-3 = 99999.999 and 1e5 - sqrt(r^2 - h^2) = 99999.9992 (to 17 digits); the
    // textbook formula gives 99999.99862 for the first.
    CHECK(expect_sphere({{0, 0, 0}, {1, 0, 0}}, {{1e5, 0, 0}, 1e-3}).t == 99999.999);
    CHECK(expect_sphere({{0, 0.6e-3, 0}, {1, 0, 0}}, {{1e5, 0, 0}, 1e-3}).t == 99999.9992);
}

TEST_CASE("expect_sphere: zero radius and zero direction miss, by the contract", "[oracle]") {
    CHECK_FALSE(expect_sphere({{0, 0, 5}, {0, 0, -1}}, {{0, 0, 0}, 0.0}).hit);
    CHECK_FALSE(expect_sphere({{0, 0, 5}, {0, 0, 0}}, {{0, 0, 0}, 1.0}).hit);
}

TEST_CASE("expect_plane: hits ahead, misses behind, parallel is near the boundary", "[oracle]") {
    const Plane floor{{0, -1, 0}, {0, 2, 0}};
    const Expectation ahead = expect_plane({{0, 3, 0}, {0, -1, 0}}, floor);
    CHECK(ahead.hit);
    CHECK(ahead.t == 4.0);
    CHECK_THAT(ahead.normal, IsNear(Vec3(0, 1, 0), 1e-15));
    CHECK_FALSE(expect_plane({{0, 3, 0}, {0, 1, 0}}, floor).hit);
    const Expectation parallel = expect_plane({{0, 3, 0}, {1, 0, 0}}, floor);
    CHECK_FALSE(parallel.hit);
    CHECK(parallel.near_boundary);
}

TEST_CASE(
    "exact_closest_primitive: the nearest exact hit, ties to the earlier in closest_hit's order",
    "[oracle]") {
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    const std::vector<CaseShape> shapes = {
        Plane{{0, 0, -20}, {0, 0, 1}},
        Sphere{{0, 0, -10}, 1.0},
        Triangle{{-1, -1, -6}, {1, -1, -6}, {0, 1, -6}},
        Sphere{{0, 0, -4}, 1.0},
    };
    CHECK(exact_closest_primitive(ray, shapes) == 3);  // t = 3
    // The triangle at t = 5 against a sphere whose near side is also at exactly t = 5: the
    // sphere comes first in closest_hit's order.
    const std::vector<CaseShape> tie = {Triangle{{-1, -1, -5}, {1, -1, -5}, {0, 1, -5}},
                                        Sphere{{0, 0, -6}, 1.0}};
    CHECK(exact_closest_primitive(ray, tie) == 1);
    CHECK(exact_closest_primitive({{0, 0, 0}, {0, 1, 0}}, shapes) == -1);
}

TEST_CASE("exact_closest_primitive: roots compared beyond double precision", "[oracle]") {
    // Radii 1 and 1 + 2^-52: near sides at t = 4 and 4 - 2^-52, which both round to 4.
    const Ray ray{{0, 0, 5}, {0, 0, -1}};
    const std::vector<CaseShape> shapes = {Sphere{{0, 0, 0}, 1.0},
                                           Sphere{{0, 0, 0}, 1.0 + 0x1p-52}};
    CHECK(exact_closest_primitive(ray, shapes) == 1);
}
