// How tight the oracle is, and what it asks of the sphere and triangle tests: every tolerance
// finite on every family and seed, near-boundary only within the rounding radius, the handout's
// sphere accepted and the lecture's discriminant not, the reference within a few ulps.

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>

#include "app/check/case_file.h"
#include "app/check/case_scoring.h"
#include "app/check/stage3_methods.h"
#include "base/testing/catch.h"
#include "grader/grade/tests/score_in_process.h"
#include "grading/3_intersect/decide_cases.h"
#include "grading/3_intersect/exact_intersection.h"
#include "grading/3_intersect/stage3_contract_cases.h"
#include "grading/3_intersect/stage3_families.h"
#include "solutions/3_intersect/intersect_methods.h"

using namespace raystep;

namespace {

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

CaseFamily decided(const char* name, std::uint64_t seed, std::size_t count) {
    const Stage3Family& family = *find_stage3_family(name);
    CaseFamily cases = generate_cases(family, seed, count);
    decide_cases(cases, family.t_ulps);
    return cases;
}

// The sphere test as the handout and the stub write it: the stable roots, the discriminant as
// a (r^2 - |f - (b / a) D|^2), and the normal (P - C) / r, not normalized again.
std::optional<Hit> handout_sphere(const Ray& ray, const Sphere& sphere) {
    if (!(sphere.radius > 0.0)) return std::nullopt;
    const Vec3 f = ray.origin - sphere.center;
    const double a = glm::dot(ray.direction, ray.direction);
    if (a == 0.0) return std::nullopt;
    const double b = glm::dot(ray.direction, f);
    const double c = glm::dot(f, f) - sphere.radius * sphere.radius;
    const Vec3 to_line = f - (b / a) * ray.direction;
    const double discriminant = a * (sphere.radius * sphere.radius - glm::dot(to_line, to_line));
    if (!(discriminant >= 0.0)) return std::nullopt;
    const double q = -(b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a;
    double t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    const auto in_range = [&](double t) { return t >= ray.t_min && t <= ray.t_max; };
    const double t = in_range(t0) ? t0 : t1;
    if (!in_range(t)) return std::nullopt;
    const Vec3 point = ray.origin + t * ray.direction;
    return Hit{t, (point - sphere.center) / sphere.radius};
}

Stage3Method sphere_method(const char* name,
                           std::optional<Hit> (*test)(const Ray&, const Sphere&)) {
    Stage3Method method{name, Stage3Method::Kind::sphere};
    method.sphere = test;
    return method;
}

// Ray-plane that calls a ray parallel when |D . N| is below 10^-exponent, as a student's
// epsilon does: every other answer is the reference's.
template <int Exponent>
std::optional<Hit> plane_with_parallel_epsilon(const Ray& ray, const Plane& plane) {
    if (std::abs(glm::dot(ray.direction, plane.normal)) < std::pow(10.0, -Exponent)) {
        return std::nullopt;
    }
    return intersect_plane(ray, plane);
}

// Which coordinate of n is largest, in magnitude or as a signed number.
int largest_axis(const Vec3& n, bool magnitude) {
    const Vec3 m = magnitude ? glm::abs(n) : n;
    return (m.x >= m.y && m.x >= m.z) ? 0 : (m.y >= m.z ? 1 : 2);
}

// The projection method that drops the signed largest coordinate of the normal: where that is
// not the largest in magnitude, the triangle projects to a segment or a sliver and the ray
// misses; elsewhere it is the reference's projection.
std::optional<Hit> projection_by_signed_axis(const Ray& ray, const Triangle& triangle) {
    const Vec3 n = glm::cross(triangle.p1 - triangle.p0, triangle.p2 - triangle.p0);
    if (largest_axis(n, false) != largest_axis(n, true)) return std::nullopt;
    return intersect_triangle_projection(ray, triangle);
}

const char* const kSphereFamilies[] = {"random-spheres", "axis-parallel", "origins-on-surface",
                                       "tangent-rays",   "tiny-spheres",  "huge-spheres",
                                       "far-spheres",    "stable-roots",  "closest-hit-scene"};

// The contract family, decided by the oracle as the grader decides it.
CaseFamily decided_contract_family() {
    CaseFamily contract = contract_family();
    decide_cases(contract);
    return contract;
}

// The exact family, decided and then held to its exact answers, as the grader holds it.
CaseFamily decided_exact_family() {
    CaseFamily exact = exact_family();
    decide_cases(exact);
    tighten_exact_family(exact);
    return exact;
}

}  // namespace

TEST_CASE("oracle: every family on many seeds has finite tolerances, and its case file loads",
          "[oracle]") {
    for (const Stage3Family& family : stage3_families()) {
        for (std::uint64_t seed = 1; seed <= 12; ++seed) {
            CAPTURE(family.name, seed);
            const CaseFamily cases = decided(family.name, seed, 150);
            for (const RayCase& ray_case : cases.cases) {
                for (const CasePrimitive& primitive : ray_case.primitives) {
                    const Expectation& e = primitive.expected;
                    if (std::isnan(e.t)) continue;
                    CAPTURE(ray_case.index);
                    REQUIRE(std::isfinite(e.t_tolerance));
                    REQUIRE(std::isfinite(e.normal_tolerance));
                    REQUIRE(std::isfinite(e.barycentric_tolerance));
                    REQUIRE(finite(e.normal));
                }
            }
            // What `raystep check` reads: the oracle's own file must load.
            std::ostringstream file;
            write_case_file(file, {cases});
            const std::vector<CaseFamily> loaded = parse_case_file(file.str(), "remade.cases");
            REQUIRE(loaded.size() == 1);
            CHECK(loaded[0].cases.size() == cases.cases.size());
        }
    }
}

TEST_CASE(
    "expect_triangle: a sliver whose double cross product rounds to zero has the exact normal",
    "[oracle]") {
    // e1 x e2 has z = (1 + 2^-52)(1 - 2^-53) - 1 = 2^-53 - 2^-105 exactly; the double product
    // rounds to 1, and the difference to 0.
    const Triangle sliver{{0, 0, 0}, {1 + 0x1p-52, 1, 0}, {1, 1 - 0x1p-53, 0}};
    const Ray ray{{0.5, 0.5, 2}, {0, 0, -1}};
    const Expectation e = expect_triangle(ray, sliver);
    REQUIRE((e.hit || e.near_boundary));
    CHECK(e.normal == Vec3(0, 0, 1));
    CHECK(std::isfinite(e.t_tolerance));
    CHECK(std::isfinite(e.normal_tolerance));
    CHECK(std::isfinite(e.barycentric_tolerance));
}

TEST_CASE("expect_sphere: a small sphere far away is near tangency only within the rounding radius",
          "[oracle]") {
    const Sphere far{{1e7, 0, 0}, 1e-3};
    // 0.09 r from the centre: deep inside, a plain hit.
    const Expectation deep = expect_sphere({{0, 0.09e-3, 0}, {1, 0, 0}}, far);
    CHECK(deep.hit);
    CHECK_FALSE(deep.near_boundary);
    CHECK(deep.normal_tolerance < 1e-3);
    // 0.999 r: still a plain hit; 1e-10 outside: within the rounding of 1e7, either way.
    CHECK_FALSE(expect_sphere({{0, 0.999e-3, 0}, {1, 0, 0}}, far).near_boundary);
    const Expectation grazing = expect_sphere({{0, 1e-3 + 1e-10, 0}, {1, 0, 0}}, far);
    CHECK_FALSE(grazing.hit);
    CHECK(grazing.near_boundary);
}

TEST_CASE("expect_sphere: normal tolerances stay far below the length of a unit vector",
          "[oracle]") {
    for (const char* name : {"tiny-spheres", "far-spheres", "huge-spheres", "random-spheres"}) {
        CAPTURE(name);
        for (const RayCase& ray_case : decided(name, 5, 400).cases) {
            const Expectation& e = ray_case.primitives[0].expected;
            CAPTURE(ray_case.index);
            if (!std::isnan(e.t)) CHECK(e.normal_tolerance < 1e-2);
        }
    }
}

TEST_CASE("score: the handout's sphere, normal (P - C) / r, passes every sphere family",
          "[oracle]") {
    const Stage3Method method = sphere_method("intersect_sphere", handout_sphere);
    std::size_t longer_than_rounding = 0;
    for (const char* name : kSphereFamilies) {
        CAPTURE(name);
        const CaseFamily cases = decided(name, 11, 300);
        const MethodScore s = score_in_process(method, cases);
        CHECK(s.passed == s.cases);
        for (const RayCase& ray_case : cases.cases) {
            for (const CasePrimitive& primitive : ray_case.primitives) {
                if (!std::holds_alternative<Sphere>(primitive.shape)) continue;
                const auto hit = handout_sphere(ray_case.ray, std::get<Sphere>(primitive.shape));
                if (hit && std::abs(glm::length(hit->normal) - 1.0) > 1e-9) ++longer_than_rounding;
            }
        }
    }
    // The normal's length is off 1 by more than a normalized vector's rounding on some cases:
    // the checker accepts it only because its length tolerance follows the normal's budget.
    CHECK(longer_than_rounding > 0);
}

TEST_CASE(
    "score: the lecture's discriminant b^2 - a c reports hits on exact misses of small spheres",
    "[oracle]") {
    const Stage3Method lecture = sphere_method("intersect_sphere", intersect_sphere_stable_roots);
    for (const char* name : {"tiny-spheres", "far-spheres"}) {
        CAPTURE(name);
        const MethodScore s = score_in_process(lecture, decided(name, 11, 300));
        CHECK(s.count(Verdict::false_hit) > 0);
        CHECK(s.exact_false_hits > 0);
    }
}

TEST_CASE("intersect_sphere: within 16 ulps of the exact t on huge, far and tiny spheres",
          "[oracle]") {
    for (const char* name : {"tiny-spheres", "far-spheres", "huge-spheres", "random-spheres"}) {
        for (std::uint64_t seed = 1; seed <= 5; ++seed) {
            CAPTURE(name, seed);
            for (const RayCase& ray_case : decided(name, seed, 400).cases) {
                const Expectation& e = ray_case.primitives[0].expected;
                const auto hit =
                    intersect_sphere(ray_case.ray, std::get<Sphere>(ray_case.primitives[0].shape));
                if (!e.hit || e.near_boundary || !hit) continue;
                CAPTURE(ray_case.index);
                CHECK(ulp_distance(hit->t, e.t) <= 16.0);
            }
        }
    }
}

TEST_CASE("reference tests: no hit of any method on any family has a NaN or infinite field",
          "[oracle]") {
    std::vector<Stage3Method> methods = stage3_methods();
    for (const Stage3Family& family : stage3_families()) {
        for (std::uint64_t seed = 1; seed <= 4; ++seed) {
            const CaseFamily cases = generate_cases(family, seed, 300);
            for (const Stage3Method& method : methods) {
                CAPTURE(family.name, seed, method.name);
                for (const RayCase& ray_case : cases.cases) {
                    const CaseAnswer answer = run_method(method, ray_case);
                    for (const std::optional<Hit>& hit : answer.hits) {
                        if (!hit) continue;
                        CAPTURE(ray_case.index);
                        REQUIRE(std::isfinite(hit->t));
                        REQUIRE(finite(hit->normal));
                        if (method.kind == Stage3Method::Kind::triangle) {
                            REQUIRE(std::isfinite(hit->beta));
                            REQUIRE(std::isfinite(hit->gamma));
                        }
                    }
                }
            }
        }
    }
}

TEST_CASE("contract cases: every reference method passes them, the exact ones with exact t",
          "[oracle]") {
    const CaseFamily contract = decided_contract_family();
    const CaseFamily exact = decided_exact_family();
    std::vector<Stage3Method> methods = stage3_methods();
    methods.push_back(sphere_method("intersect_sphere", intersect_sphere_stable_roots));
    methods.push_back(sphere_method("intersect_sphere", handout_sphere));
    Stage3Method moller_trumbore{"intersect_triangle", Stage3Method::Kind::triangle};
    moller_trumbore.triangle = intersect_triangle_moller_trumbore;
    methods.push_back(moller_trumbore);
    for (const CaseFamily* family : {&contract, &exact}) {
        for (const Stage3Method& method : methods) {
            CAPTURE(family->name, method.name);
            const MethodScore s = score_in_process(method, *family);
            const std::string first_failure =
                s.counterexamples.empty() ? "" : s.counterexamples.front().detail;
            CAPTURE(first_failure);
            CHECK(s.passed == s.cases);
        }
    }
}

TEST_CASE("contract cases: the exact ones are decided strictly, nothing near a boundary",
          "[oracle]") {
    const CaseFamily exact = decided_exact_family();
    for (const RayCase& ray_case : exact.cases) {
        for (const CasePrimitive& primitive : ray_case.primitives)
            CHECK_FALSE(primitive.expected.near_boundary);
    }
}

TEST_CASE("contract cases: they fail a plane epsilon and a projection by the signed axis",
          "[oracle]") {
    const CaseFamily contract = decided_contract_family();
    const CaseFamily exact = decided_exact_family();
    const auto plane = [](std::optional<Hit> (*test)(const Ray&, const Plane&)) {
        Stage3Method method{"intersect_plane", Stage3Method::Kind::plane};
        method.plane = test;
        return method;
    };
    // The oracle's cases reach D . N = 1e-13; only the exact ones go below its grazing bound.
    CHECK(score_in_process(plane(plane_with_parallel_epsilon<6>), contract).passed <
          score_in_process(plane(intersect_plane), contract).passed);
    CHECK(score_in_process(plane(plane_with_parallel_epsilon<12>), contract).passed <
          score_in_process(plane(intersect_plane), contract).passed);
    CHECK(score_in_process(plane(plane_with_parallel_epsilon<15>), exact).passed <
          score_in_process(plane(intersect_plane), exact).passed);

    Stage3Method signed_axis{"intersect_triangle_projection", Stage3Method::Kind::triangle};
    signed_axis.triangle = projection_by_signed_axis;
    const MethodScore s = score_in_process(signed_axis, contract);
    // Every triangle whose normal lies on or next to a negative axis: three tilts and a ray from
    // behind, on each axis.
    CHECK(s.cases - s.passed >= 12);
}
