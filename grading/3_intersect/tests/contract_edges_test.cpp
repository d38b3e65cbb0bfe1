// Stage 3's contract edges (grading/3_intersect/stage3_contract_edges.h), decided as the grader's
// stage3.contract checks decide them: every right form of every function passes every case on
// every seed, and a function that breaks the sentence fails a case on every seed.

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "app/check/case_scoring.h"
#include "app/check/stage3_methods.h"
#include "base/testing/catch.h"
#include "grader/grade/tests/score_in_process.h"
#include "grading/3_intersect/collinear_triangles.h"
#include "grading/3_intersect/decide_cases.h"
#include "grading/3_intersect/stage3_contract_cases.h"
#include "grading/3_intersect/stage3_contract_edges.h"
#include "solutions/3_intersect/intersect_methods.h"

using namespace raystep;

namespace {

// The seeds the power of each check is claimed over (docs/measurements/stage3-check-power.md).
constexpr std::uint64_t kSeeds = 100;
constexpr std::size_t kDrawn = 24;  // as stage3_contract_checks.cpp draws

CaseFamily decided_family(CaseFamily (*family)(std::uint64_t, std::size_t), std::uint64_t seed,
                          bool exact) {
    CaseFamily cases = family(seed, kDrawn);
    decide_cases(cases);
    if (exact) tighten_exact_family(cases);
    return cases;
}

template <typename Shape>
Stage3Method method(const char* name, std::optional<Hit> (*test)(const Ray&, const Shape&)) {
    Stage3Method m{name, Stage3Method::Kind::closest};
    if constexpr (std::is_same_v<Shape, Sphere>) {
        m.kind = Stage3Method::Kind::sphere;
        m.sphere = test;
    } else if constexpr (std::is_same_v<Shape, Triangle>) {
        m.kind = Stage3Method::Kind::triangle;
        m.triangle = test;
    } else {
        m.kind = Stage3Method::Kind::plane;
        m.plane = test;
    }
    return m;
}

// Every function of intersect.h as the reference writes it, and the other right forms the
// reference keeps: Moller-Trumbore, the watertight test, the stable roots with b^2 - a c.
std::vector<Stage3Method> right_forms() {
    std::vector<Stage3Method> forms = stage3_methods();
    forms.push_back(method("intersect_triangle", intersect_triangle_moller_trumbore));
    forms.push_back(method("intersect_triangle", intersect_triangle_watertight));
    forms.push_back(method("intersect_sphere", intersect_sphere_stable_roots));
    return forms;
}

// The reference's test on a range open at one end: [t_min, t_max) or (t_min, t_max].
template <typename Shape, std::optional<Hit> (*Test)(const Ray&, const Shape&)>
std::optional<Hit> open_at_t_max(const Ray& ray, const Shape& shape) {
    Ray open = ray;
    open.t_max = std::nextafter(ray.t_max, -HUGE_VAL);
    return Test(open, shape);
}

template <typename Shape, std::optional<Hit> (*Test)(const Ray&, const Shape&)>
std::optional<Hit> open_at_t_min(const Ray& ray, const Shape& shape) {
    Ray open = ray;
    open.t_min = std::nextafter(ray.t_min, HUGE_VAL);
    return Test(open, shape);
}

// A plane test that takes a ray lying in the plane as a hit at t_min (3-plane-ray-in-plane-hits).
std::optional<Hit> plane_in_plane_hits(const Ray& ray, const Plane& plane) {
    if (glm::dot(ray.direction, plane.normal) == 0.0 &&
        glm::dot(plane.point - ray.origin, plane.normal) == 0.0 && plane.normal != Vec3(0.0)) {
        return Hit{ray.t_min, glm::normalize(plane.normal)};
    }
    return intersect_plane(ray, plane);
}

// The handout's Cramer's rule without a test for a zero normal: glm normalizes a zero vector to
// NaN (3-cramer-collinear-nan-normal).
std::optional<Hit> cramer_without_normal_test(const Ray& ray, const Triangle& tri) {
    const auto det = [](const Vec3& a, const Vec3& b, const Vec3& c) {
        return glm::dot(a, glm::cross(b, c));
    };
    const Vec3 c0 = tri.p0 - tri.p1;
    const Vec3 c1 = tri.p0 - tri.p2;
    const Vec3 rhs = tri.p0 - ray.origin;
    const double m = det(c0, c1, ray.direction);
    if (m == 0.0) return std::nullopt;
    const double t = det(c0, c1, rhs) / m;
    if (!(t >= ray.t_min && t <= ray.t_max)) return std::nullopt;
    const double gamma = det(c0, rhs, ray.direction) / m;
    if (!(gamma >= 0.0 && gamma <= 1.0)) return std::nullopt;
    const double beta = det(rhs, c1, ray.direction) / m;
    if (!(beta >= 0.0 && beta <= 1.0 - gamma)) return std::nullopt;
    return Hit{t, glm::normalize(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0)), beta, gamma};
}

// closest_hit as 3-closest-hit-ties-to-last writes it, with the reference's tests: a hit at the
// best t so far replaces it. Its answer, by the case's primitive index.
CaseAnswer ties_to_last(const RayCase& ray_case) {
    CaseAnswer answer;
    answer.hits.resize(ray_case.primitives.size());
    Ray nearer = ray_case.ray;
    for (const std::size_t kind : {0u, 1u, 2u}) {
        for (std::size_t k = 0; k < ray_case.primitives.size(); ++k) {
            const CaseShape& shape = ray_case.primitives[k].shape;
            if (shape.index() != kind) continue;
            std::optional<Hit> hit;
            if (const auto* s = std::get_if<Sphere>(&shape)) hit = intersect_sphere(nearer, *s);
            if (const auto* t = std::get_if<Triangle>(&shape)) hit = intersect_triangle(nearer, *t);
            if (const auto* p = std::get_if<Plane>(&shape)) hit = intersect_plane(nearer, *p);
            if (hit && (!answer.closest_hit || hit->t <= answer.closest_hit->t)) {
                answer.closest_hit = hit;
                answer.closest_primitive = k;
                nearer.t_max = hit->t;
            }
        }
    }
    return answer;
}

}  // namespace

TEST_CASE("contract edges: every right form of every function passes every case, 20 seeds",
          "[oracle]") {
    const std::vector<Stage3Method> forms = right_forms();
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        for (const CaseFamily& family :
             {decided_family(range_end_family, seed, true), decided_family(tie_family, seed, true),
              decided_family(in_plane_family, seed, true),
              decided_family(degenerate_family, seed, false)}) {
            for (const Stage3Method& form : forms) {
                const MethodScore s = score_in_process(form, family);
                CAPTURE(seed, family.name, form.name);
                CAPTURE(s.counterexamples.empty() ? "" : s.counterexamples.front().detail);
                CHECK(s.passed == s.cases);
            }
        }
    }
}

TEST_CASE("contract edges: the exact families leave nothing to rounding", "[oracle]") {
    for (const CaseFamily& family :
         {decided_family(range_end_family, 1, true), decided_family(tie_family, 1, true),
          decided_family(in_plane_family, 1, true)}) {
        for (const RayCase& ray_case : family.cases) {
            for (const CasePrimitive& primitive : ray_case.primitives) {
                CAPTURE(family.name, ray_case.index);
                CHECK_FALSE(primitive.expected.near_boundary);
                CHECK(std::isnan(primitive.expected.t_alternative));
                if (primitive.expected.hit) CHECK(primitive.expected.t_tolerance == 0.0);
            }
        }
    }
}

TEST_CASE(
    "contract edges: a range open at either end fails range-ends in every function, every "
    "seed",
    "[oracle]") {
    const std::vector<Stage3Method> open_forms = {
        method("intersect_plane", open_at_t_max<Plane, intersect_plane>),
        method("intersect_plane", open_at_t_min<Plane, intersect_plane>),
        method("intersect_triangle_cramer", open_at_t_max<Triangle, intersect_triangle_cramer>),
        method("intersect_triangle_cramer", open_at_t_min<Triangle, intersect_triangle_cramer>),
        method("intersect_triangle_projection",
               open_at_t_max<Triangle, intersect_triangle_projection>),
        method("intersect_triangle_halfspaces",
               open_at_t_min<Triangle, intersect_triangle_halfspaces>),
        method("intersect_sphere", open_at_t_max<Sphere, intersect_sphere>),
        method("intersect_sphere", open_at_t_min<Sphere, intersect_sphere>),
    };
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const CaseFamily family = decided_family(range_end_family, seed, true);
        for (std::size_t k = 0; k < open_forms.size(); ++k) {
            CAPTURE(seed, k);
            const MethodScore s = score_in_process(open_forms[k], family);
            CHECK(s.passed < s.cases);
        }
    }
}

TEST_CASE("contract edges: a tie given to the last primitive fails ties on every seed",
          "[oracle]") {
    const Stage3Method closest{"closest_hit", Stage3Method::Kind::closest};
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const CaseFamily family = decided_family(tie_family, seed, true);
        std::size_t wrong = 0;
        for (const RayCase& ray_case : family.cases) {
            std::string detail;
            if (score_case(closest, ray_case, ties_to_last(ray_case), detail) ==
                Verdict::wrong_primitive) {
                ++wrong;
            }
        }
        CAPTURE(seed);
        CHECK(wrong == family.cases.size());
    }
}

TEST_CASE("contract edges: a ray lying in a plane taken as a hit fails rays-in-plane on every seed",
          "[oracle]") {
    const Stage3Method in_plane_hits = method("intersect_plane", plane_in_plane_hits);
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const MethodScore s =
            score_in_process(in_plane_hits, decided_family(in_plane_family, seed, true));
        CAPTURE(seed);
        CHECK(s.count(Verdict::false_hit) >= 2);
    }
}

TEST_CASE(
    "contract edges: Cramer's rule without a zero-normal test gives a NaN normal on every "
    "seed",
    "[oracle]") {
    const Stage3Method cramer = method("intersect_triangle_cramer", cramer_without_normal_test);
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const MethodScore s =
            score_in_process(cramer, decided_family(degenerate_family, seed, false));
        CAPTURE(seed);
        CHECK(s.count(Verdict::not_finite) >= 1);
    }
}

TEST_CASE(
    "collinear triangles: every draw is exactly collinear and trips the form it was drawn "
    "for",
    "[oracle]") {
    for (const SolveForm form : {SolveForm::cramer, SolveForm::moller_trumbore}) {
        for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
            PortableRandom random(seed, 0);
            const CollinearCase drawn = collinear_case(random, form);
            const Triangle& tri = drawn.triangle;
            CAPTURE(seed, static_cast<int>(form));
            CHECK(drawn.trips);
            CHECK(form_reports_hit(form, drawn.ray, tri));
            CHECK(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0) == Vec3(0.0));
        }
    }
}

TEST_CASE("contract edges: the cross-kind tie goes to the sphere, listed last", "[oracle]") {
    // A plane, a triangle and a sphere all at t = 5, listed plane first: closest_hit must choose
    // the sphere.
    const CaseFamily ties = decided_family(tie_family, 1, true);
    const auto tie = std::find_if(ties.cases.begin(), ties.cases.end(), [](const RayCase& c) {
        return c.primitives.size() == 3 && std::holds_alternative<Plane>(c.primitives[0].shape) &&
               std::holds_alternative<Sphere>(c.primitives[2].shape);
    });
    REQUIRE(tie != ties.cases.end());
    const Stage3Method closest{"closest_hit", Stage3Method::Kind::closest};
    CaseAnswer plane_first;
    plane_first.hits.resize(3);
    plane_first.closest_hit = Hit{5.0, Vec3(0, 0, 1)};
    plane_first.closest_primitive = 0;
    std::string detail;
    CHECK(score_case(closest, *tie, plane_first, detail) == Verdict::wrong_primitive);
    CaseAnswer sphere_chosen = plane_first;
    sphere_chosen.closest_primitive = 2;
    CHECK(score_case(closest, *tie, sphere_chosen, detail) == Verdict::pass);
}
