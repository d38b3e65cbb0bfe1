// The oracle against independent judges on seeded random rays: CGAL's own ray-triangle test,
// and the reference solutions, which must agree with it away from every boundary (to within the
// tolerances it reports). A failure here means the oracle, or its rounding budget, is wrong.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <glm/geometric.hpp>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "grading/3_intersect/exact_intersection.h"
#include "solutions/3_intersect/intersect_methods.h"

using namespace raystep;

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;

// A ray from outside the box, aimed at a random point of the triangle or a little beside it.
Ray ray_towards(PortableRandom& random, const Triangle& tri) {
    const double beta = random.uniform(-0.2, 1.2);
    const double gamma = random.uniform(-0.2, 1.2);
    const Vec3 target = tri.p0 + beta * (tri.p1 - tri.p0) + gamma * (tri.p2 - tri.p0);
    const Vec3 origin = random.point(8.0) + Vec3(0, 0, 10);
    return {origin, target - origin};
}

using TriangleTest = std::optional<Hit> (*)(const Ray&, const Triangle&);
const std::pair<const char*, TriangleTest> kTriangleTests[] = {
    {"projection", intersect_triangle_projection},
    {"halfspaces", intersect_triangle_halfspaces},
    {"cramer", intersect_triangle_cramer},
    {"watertight", intersect_triangle_watertight},
    {"moller_trumbore", intersect_triangle_moller_trumbore},
};

}  // namespace

TEST_CASE("oracle: agrees with CGAL's ray-triangle test on random rays", "[oracle]") {
    int hits = 0;
    for (int k = 0; k < 3000; ++k) {
        PortableRandom random(101, k);
        const Triangle tri{random.point(2), random.point(2), random.point(2)};
        const Ray ray = ray_towards(random, tri);
        CAPTURE(k);
        const Expectation e = expect_triangle(ray, tri);
        const Kernel::Ray_3 cgal_ray(
            {ray.origin.x, ray.origin.y, ray.origin.z},
            Kernel::Vector_3(ray.direction.x, ray.direction.y, ray.direction.z));
        const Kernel::Triangle_3 cgal_triangle({tri.p0.x, tri.p0.y, tri.p0.z},
                                               {tri.p1.x, tri.p1.y, tri.p1.z},
                                               {tri.p2.x, tri.p2.y, tri.p2.z});
        CHECK(e.hit == CGAL::do_intersect(cgal_ray, cgal_triangle));
        hits += e.hit;
    }
    CHECK(hits > 500);
}

TEST_CASE("oracle: every reference triangle test agrees away from the boundaries", "[oracle]") {
    int decided = 0;
    for (int k = 0; k < 3000; ++k) {
        PortableRandom random(102, k);
        const Triangle tri{random.point(2), random.point(2), random.point(2)};
        const Ray ray = ray_towards(random, tri);
        const Expectation e = expect_triangle(ray, tri);
        if (e.near_boundary) continue;
        ++decided;
        for (const auto& [name, test] : kTriangleTests) {
            CAPTURE(k, name);
            const std::optional<Hit> hit = test(ray, tri);
            REQUIRE(hit.has_value() == e.hit);
            if (hit) {
                CHECK(std::abs(hit->t - e.t) <= e.t_tolerance);
                CHECK(std::abs(hit->beta - e.beta) <= e.barycentric_tolerance);
                CHECK(std::abs(hit->gamma - e.gamma) <= e.barycentric_tolerance);
                CHECK(glm::length(hit->normal - e.normal) <= e.normal_tolerance);
            }
        }
    }
    CHECK(decided > 2500);
}

TEST_CASE("oracle: the reference sphere tests agree away from the boundaries", "[oracle]") {
    int decided = 0;
    for (int k = 0; k < 3000; ++k) {
        PortableRandom random(103, k);
        const Sphere sphere{random.point(2), random.uniform(0.1, 3.0)};
        const Vec3 origin = random.point(8.0);
        const Vec3 target = sphere.center + random.point(sphere.radius * 1.2);
        const Ray ray{origin, target - origin};
        const Expectation e = expect_sphere(ray, sphere);
        if (e.near_boundary) continue;
        ++decided;
        for (const auto& [name, test] :
             {std::pair{"intersect_sphere", intersect_sphere},
              std::pair{"stable_roots", intersect_sphere_stable_roots}}) {
            CAPTURE(k, name);
            const std::optional<Hit> hit = test(ray, sphere);
            REQUIRE(hit.has_value() == e.hit);
            if (hit) {
                const bool first = std::abs(hit->t - e.t) <= e.t_tolerance;
                const bool alternative = std::abs(hit->t - e.t_alternative) <= e.t_tolerance;
                CHECK((first || alternative));
                CHECK(glm::length(hit->normal - (first ? e.normal : e.normal_alternative)) <=
                      e.normal_tolerance);
            }
        }
    }
    CHECK(decided > 2500);
}

TEST_CASE("oracle: the normwise budget cannot tell the root forms apart; ulps can", "[oracle]") {
    // Just outside a sphere of radius 5e7: the stable roots give t = 1e-8, the textbook formula
    // 7.45e-9. Measured against the coordinates (5e7, whose ulp is 7.5e-9) both are within
    // rounding, so the budget accepts both. What the stable form buys is relative accuracy of
    // the small root: within a few ulps of t itself, where the textbook form is 25% off. The
    // stable-roots family checks exactly that (grading/3_intersect).
    const Ray ray{{1, 5e7, 0}, {0, -1, 0}};
    const Sphere large{{0, 0, 0}, 5e7};
    const Expectation e = expect_sphere(ray, large);
    REQUIRE(e.hit);
    const double stable = intersect_sphere_stable_roots(ray, large)->t;
    const double textbook = intersect_sphere_textbook(ray, large)->t;
    CHECK(std::abs(stable - e.t) <= e.t_tolerance);
    CHECK(std::abs(textbook - e.t) <= e.t_tolerance);
    const double ulp = std::nextafter(e.t, 1.0) - e.t;
    CHECK(std::abs(stable - e.t) <= 4 * ulp);
    CHECK(std::abs(textbook - e.t) > 1e6 * ulp);

    // A 1 mm sphere 100 km away: b^2 - a c keeps no digits worth the name in either form, and
    // the budget does not excuse it: moving the inputs by their rounding moves t by nanometres,
    // the lecture's discriminant by 0.4 mm. The reference, which rewrites the discriminant, is
    // within two ulps.
    const Ray far_ray{{0, 0, 0}, {1, 0, 0}};
    const Sphere far{{1e5, 0, 0}, 1e-3};
    const Expectation far_e = expect_sphere(far_ray, far);
    CHECK(std::abs(intersect_sphere_stable_roots(far_ray, far)->t - far_e.t) > far_e.t_tolerance);
    CHECK(std::abs(intersect_sphere_textbook(far_ray, far)->t - far_e.t) > far_e.t_tolerance);
    const double far_ulp = std::nextafter(far_e.t, 1e6) - far_e.t;
    CHECK(std::abs(intersect_sphere(far_ray, far)->t - far_e.t) <= 2 * far_ulp);
}
