#include "app/check/case_scoring.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "app/check/case_file.h"
#include "base/testing/catch.h"
#include "base/testing/special_values.h"
#include "base/testing/vec3_matchers.h"

using namespace raystep;

namespace Catch {
template <>
struct StringMaker<Verdict> {
    static std::string convert(Verdict verdict) { return verdict_name(verdict); }
};
}  // namespace Catch

namespace {

using Kind = Stage3Method::Kind;

// Scoring never calls a method's functions, only looks at its name and kind.
const Stage3Method kSphereTest{"intersect_sphere", Kind::sphere};
const Stage3Method kTriangleTest{"intersect_triangle_cramer", Kind::triangle};
const Stage3Method kClosest{"closest_hit", Kind::closest};

// Shapes: scoring reads only their kind.
const Sphere kSphere{{0.0, 0.0, 0.0}, 1.0};
const Triangle kTriangle{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}};
const Plane kPlane{{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}};

using raystep::testing::kNaN;
const Vec3 kUp{0.0, 0.0, 1.0};

// Tolerances that are exact in binary, so that a test can sit right on them.
constexpr double kTTolerance = 0.25;
constexpr double kNormalTolerance = 0.125;
constexpr double kBarycentricTolerance = 0.0625;

Expectation expect_hit(double t, const Vec3& normal = kUp) {
    Expectation e;
    e.hit = true;
    e.t = t;
    e.t_tolerance = kTTolerance;
    e.normal = normal;
    e.normal_tolerance = kNormalTolerance;
    return e;
}

Expectation expect_triangle_hit(double t, double beta, double gamma) {
    Expectation e = expect_hit(t);
    e.beta = beta;
    e.gamma = gamma;
    e.barycentric_tolerance = kBarycentricTolerance;
    return e;
}

Expectation expect_miss() {
    return {};
}

Expectation near_boundary(Expectation e) {
    e.near_boundary = true;
    return e;
}

// A near-boundary miss that carries the point where a nearby ray would cross.
Expectation near_miss_crossing(double t) {
    Expectation e = near_boundary(expect_triangle_hit(t, 1.0, 0.0));
    e.hit = false;
    return e;
}

Hit hit_at(double t, const Vec3& normal = kUp, double beta = 0.0, double gamma = 0.0) {
    return {t, normal, beta, gamma};
}

RayCase make_case(std::vector<CasePrimitive> primitives, bool watertight = false,
                  std::uint64_t index = 0) {
    RayCase ray_case;
    ray_case.index = index;
    ray_case.ray = {{0.0, 0.0, 10.0}, {0.0, 0.0, -1.0}};
    ray_case.primitives = std::move(primitives);
    ray_case.watertight = watertight;
    return ray_case;
}

CaseAnswer answer(std::vector<std::optional<Hit>> hits) {
    CaseAnswer a;
    a.hits = std::move(hits);
    return a;
}

CaseAnswer closest_answer(std::optional<std::size_t> primitive, std::optional<Hit> hit) {
    CaseAnswer a;
    a.closest_primitive = primitive;
    a.closest_hit = hit;
    return a;
}

struct Scored {
    Verdict verdict;
    std::string detail;
};

Scored score(const Stage3Method& method, const RayCase& ray_case, const CaseAnswer& a) {
    Scored result;
    result.verdict = score_case(method, ray_case, a, result.detail);
    return result;
}

// Two triangles of a closed mesh, the ray through their shared edge.
RayCase shared_edge_case(bool watertight) {
    return make_case({{kTriangle, near_boundary(expect_triangle_hit(5.0, 0.5, 0.5))},
                      {kTriangle, near_boundary(expect_triangle_hit(5.0, 0.0, 0.5))}},
                     watertight);
}

// A sphere at t = 7, a triangle at t = 5 and a plane at t = 15: the triangle is nearest.
RayCase three_hits_case() {
    return make_case({{kSphere, expect_hit(7.0)},
                      {kTriangle, expect_triangle_hit(5.0, 0.25, 0.5)},
                      {kPlane, expect_hit(15.0)}});
}

}  // namespace

TEST_CASE("score_case: right hits and misses pass", "[app]") {
    const RayCase ray_case =
        make_case({{kTriangle, expect_triangle_hit(5.0, 0.25, 0.5)}, {kTriangle, expect_miss()}});
    const Scored scored =
        score(kTriangleTest, ray_case, answer({hit_at(5.0, kUp, 0.25, 0.5), std::nullopt}));
    CHECK(scored.verdict == Verdict::pass);
    CHECK(scored.detail.empty());
}

TEST_CASE("score_case: a miss where the exact answer is a clear hit is a false miss", "[app]") {
    const RayCase ray_case =
        make_case({{kTriangle, expect_miss()}, {kTriangle, expect_triangle_hit(5.0, 0.25, 0.5)}});
    const Scored scored = score(kTriangleTest, ray_case, answer({std::nullopt, std::nullopt}));
    CHECK(scored.verdict == Verdict::false_miss);
    CHECK(scored.detail == "primitive 1 (triangle): expected a hit at t = 5, got a miss");
}

TEST_CASE("score_case: a hit where the exact answer is a clear miss is a false hit", "[app]") {
    const RayCase ray_case = make_case({{kSphere, expect_miss()}});
    const Scored scored = score(kSphereTest, ray_case, answer({hit_at(2.5)}));
    CHECK(scored.verdict == Verdict::false_hit);
    CHECK(scored.detail == "primitive 0 (sphere): expected a miss, got a hit at t = 2.5");
}

TEST_CASE("score_case: near a boundary either answer passes, and a hit is still measured",
          "[app]") {
    const RayCase ray_case = make_case({{kTriangle, near_boundary(expect_triangle_hit(5, 0, 1))},
                                        {kTriangle, near_miss_crossing(5.0)}});
    for (const bool first : {false, true}) {
        for (const bool second : {false, true}) {
            CAPTURE(first, second);
            const std::optional<Hit> hit_first =
                first ? std::optional<Hit>(hit_at(5.0, kUp, 0.0, 1.0)) : std::nullopt;
            const std::optional<Hit> hit_second =
                second ? std::optional<Hit>(hit_at(5.0, kUp, 1.0, 0.0)) : std::nullopt;
            CHECK(score(kTriangleTest, ray_case, answer({hit_first, hit_second})).verdict ==
                  Verdict::pass);
        }
    }
    // The crossing point of a near-boundary miss is where a reported hit must be.
    CHECK(score(kTriangleTest, ray_case, answer({std::nullopt, hit_at(6.0, kUp, 1.0, 0.0)}))
              .verdict == Verdict::wrong_t);
}

TEST_CASE("score_case: a reported hit with a NaN or infinite value is not finite", "[app]") {
    const RayCase ray_case = make_case({{kTriangle, expect_triangle_hit(5.0, 0.25, 0.5)}});
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<Hit> broken = {hit_at(kNaN, kUp, 0.25, 0.5),
                                     hit_at(5.0, {0.0, inf, 1.0}, 0.25, 0.5),
                                     hit_at(5.0, kUp, kNaN, 0.5), hit_at(5.0, kUp, 0.25, -inf)};
    for (std::size_t k = 0; k < broken.size(); ++k) {
        CAPTURE(k);
        const Scored scored = score(kTriangleTest, ray_case, answer({broken[k]}));
        CHECK(scored.verdict == Verdict::not_finite);
        CHECK(scored.detail.find("primitive 0 (triangle): reported a hit with a value that is "
                                 "not finite") == 0);
    }
    // A sphere's barycentrics mean nothing, so they are not looked at.
    const RayCase sphere_case = make_case({{kSphere, expect_hit(5.0)}});
    CHECK(score(kSphereTest, sphere_case, answer({hit_at(5.0, kUp, kNaN, kNaN)})).verdict ==
          Verdict::pass);
}

TEST_CASE("score_case: t passes within its tolerance and fails beyond it", "[app]") {
    const RayCase ray_case = make_case({{kSphere, expect_hit(5.0)}});
    CHECK(score(kSphereTest, ray_case, answer({hit_at(5.0 + kTTolerance)})).verdict ==
          Verdict::pass);
    CHECK(score(kSphereTest, ray_case, answer({hit_at(5.0 - kTTolerance)})).verdict ==
          Verdict::pass);
    const Scored scored =
        score(kSphereTest, ray_case, answer({hit_at(std::nextafter(5.0 + kTTolerance, 6.0))}));
    CHECK(scored.verdict == Verdict::wrong_t);
    CHECK(scored.detail ==
          "primitive 0 (sphere): expected t = 5 within 0.25, got t = 5.2500000000000009, off by "
          "0.25000000000000089");
}

TEST_CASE("score_case: a normal must be unit length and near the expected one", "[app]") {
    Expectation loose = expect_hit(5.0);
    loose.normal_tolerance = 0.5;
    const RayCase loose_case = make_case({{kSphere, loose}});
    // Twice as long: off 1 by more than the tolerance allows any normal near a unit one.
    const Scored long_normal = score(kSphereTest, loose_case, answer({hit_at(5.0, {0, 0, 2.0})}));
    CHECK(long_normal.verdict == Verdict::wrong_normal);
    CHECK(long_normal.detail.find("has length 2, not 1") != std::string::npos);
    // Unit length within 1e-9 passes.
    CHECK(score(kSphereTest, loose_case, answer({hit_at(5.0, {0, 0, 1.0 + 5e-10})})).verdict ==
          Verdict::pass);

    const RayCase ray_case = make_case({{kSphere, expect_hit(5.0)}});
    const Scored tilted = score(kSphereTest, ray_case, answer({hit_at(5.0, {0.6, 0.0, 0.8})}));
    CHECK(tilted.verdict == Verdict::wrong_normal);
    CHECK(tilted.detail ==
          "primitive 0 (sphere): expected the normal (0, 0, 1) within 0.125, got "
          "(0.59999999999999998, 0, 0.80000000000000004)");
}

TEST_CASE("score_case: a normal's length may be off 1 by its tolerance, as (P - C) / r is",
          "[app]") {
    // A small sphere far away: the hit point is known to 1e-6 of r, and so is |P - C| / r.
    Expectation far = expect_hit(5.0);
    far.normal_tolerance = 1e-6;
    const RayCase ray_case = make_case({{kSphere, far}});
    CHECK(score(kSphereTest, ray_case, answer({hit_at(5.0, {0, 0, 1.0 + 5e-7})})).verdict ==
          Verdict::pass);
    CHECK(score(kSphereTest, ray_case, answer({hit_at(5.0, {0, 0, 1.0 + 2e-6})})).verdict ==
          Verdict::wrong_normal);
}

TEST_CASE("score_case: a triangle's beta and gamma must each be within tolerance", "[app]") {
    const RayCase ray_case = make_case({{kTriangle, expect_triangle_hit(5.0, 0.25, 0.5)}});
    CHECK(score(kTriangleTest, ray_case, answer({hit_at(5.0, kUp, 0.3125, 0.4375)})).verdict ==
          Verdict::pass);
    CHECK(score(kTriangleTest, ray_case, answer({hit_at(5.0, kUp, 0.375, 0.5)})).verdict ==
          Verdict::wrong_barycentrics);
    const Scored scored = score(kTriangleTest, ray_case, answer({hit_at(5.0, kUp, 0.25, 0.625)}));
    CHECK(scored.verdict == Verdict::wrong_barycentrics);
    CHECK(scored.detail ==
          "primitive 0 (triangle): expected barycentrics (beta, gamma) = "
          "(0.25, 0.5) within 0.0625, got (0.25, 0.625)");
}

TEST_CASE("score_case: a sphere's alternative hit passes with its own normal", "[app]") {
    Expectation on_surface = expect_hit(0.0);
    on_surface.t_alternative = 2.0;
    on_surface.normal_alternative = {0.0, 0.0, -1.0};
    const RayCase ray_case = make_case({{kSphere, on_surface}});
    CHECK(score(kSphereTest, ray_case, answer({hit_at(0.0)})).verdict == Verdict::pass);
    CHECK(score(kSphereTest, ray_case, answer({hit_at(2.0, {0, 0, -1})})).verdict == Verdict::pass);
    CHECK(score(kSphereTest, ray_case, answer({hit_at(2.0)})).verdict == Verdict::wrong_normal);
    CHECK(score(kSphereTest, ray_case, answer({hit_at(1.0)})).verdict == Verdict::wrong_t);
}

TEST_CASE("score_case: the earliest rule decides when several fail", "[app]") {
    const RayCase ray_case =
        make_case({{kTriangle, expect_triangle_hit(5.0, 0.25, 0.5)}, {kTriangle, expect_miss()}});
    // A wrong t on the first primitive and a false hit on the second: false hit comes first.
    CHECK(score(kTriangleTest, ray_case,
                answer({hit_at(9.0, kUp, 0.25, 0.5), hit_at(1.0, kUp, 0.0, 0.0)}))
              .verdict == Verdict::false_hit);
    // A false miss on the first and a NaN on the second: not finite comes first.
    CHECK(score(kTriangleTest, ray_case, answer({std::nullopt, hit_at(kNaN)})).verdict ==
          Verdict::not_finite);
    // A wrong t and a wrong normal on one hit: the t.
    CHECK(score(kTriangleTest, ray_case, answer({hit_at(9.0, {1, 0, 0}, 0.25, 0.5), std::nullopt}))
              .verdict == Verdict::wrong_t);
}

TEST_CASE("score_case: an exception is 'threw', whatever else the answer holds", "[app]") {
    const RayCase ray_case = make_case({{kTriangle, expect_miss()}});
    CaseAnswer threw = answer({hit_at(kNaN)});
    threw.error = "division by zero";
    const Scored scored = score(kTriangleTest, ray_case, threw);
    CHECK(scored.verdict == Verdict::threw);
    CHECK(scored.detail == "intersect_triangle_cramer threw: division by zero");
}

TEST_CASE("score_case: only the primitives the method tests count", "[app]") {
    const RayCase ray_case = make_case({{kSphere, expect_hit(7.0)},
                                        {kTriangle, expect_triangle_hit(5.0, 0.25, 0.5)},
                                        {kPlane, expect_hit(15.0)}});
    CHECK(score(kSphereTest, ray_case, answer({hit_at(7.0), std::nullopt, std::nullopt})).verdict ==
          Verdict::pass);
    // An answer list too short (from an untrusted probe) reads as misses.
    CHECK(score(kTriangleTest, ray_case, answer({})).verdict == Verdict::false_miss);
}

TEST_CASE("score_case: a watertight case leaks when no neighbour reports the hit", "[app]") {
    const RayCase watertight = shared_edge_case(true);
    const Scored leaked = score(kTriangleTest, watertight, answer({std::nullopt, std::nullopt}));
    CHECK(leaked.verdict == Verdict::leak);
    CHECK(leaked.detail ==
          "the ray meets the closed mesh (primitive 0 (triangle) at t = 5) and no "
          "primitive reported a hit: the ray slipped through");
    CHECK(score(kTriangleTest, watertight, answer({std::nullopt, hit_at(5.0, kUp, 0.0, 0.5)}))
              .verdict == Verdict::pass);
    // The same two misses pass where the primitives are not a closed mesh.
    CHECK(score(kTriangleTest, shared_edge_case(false), answer({std::nullopt, std::nullopt}))
              .verdict == Verdict::pass);
    // A clear hit missed is a false miss first.
    const RayCase clear = make_case({{kTriangle, expect_triangle_hit(5.0, 0.25, 0.25)}}, true);
    CHECK(score(kTriangleTest, clear, answer({std::nullopt})).verdict == Verdict::false_miss);
}

TEST_CASE("score_case: closest_hit must report the nearest hit, mapped to its primitive", "[app]") {
    const RayCase ray_case = three_hits_case();
    CHECK(score(kClosest, ray_case, closest_answer(1, hit_at(5.0, kUp, 0.25, 0.5))).verdict ==
          Verdict::pass);

    const Scored missed = score(kClosest, ray_case, closest_answer(std::nullopt, std::nullopt));
    CHECK(missed.verdict == Verdict::false_miss);
    CHECK(missed.detail ==
          "expected the closest hit on primitive 1 (triangle) at t = 5, got a miss");

    const Scored farther = score(kClosest, ray_case, closest_answer(0, hit_at(7.0)));
    CHECK(farther.verdict == Verdict::wrong_primitive);
    CHECK(farther.detail ==
          "closest_hit chose primitive 0 (sphere) at t = 7, but primitive 1 "
          "(triangle) is hit nearer, at t = 5");

    CHECK(score(kClosest, ray_case, closest_answer(1, hit_at(6.0, kUp, 0.25, 0.5))).verdict ==
          Verdict::wrong_t);
    CHECK(score(kClosest, ray_case, closest_answer(1, hit_at(5.0, kUp, 0.5, 0.5))).verdict ==
          Verdict::wrong_barycentrics);
    CHECK(score(kClosest, ray_case, closest_answer(1, hit_at(kNaN, kUp, 0.25, 0.5))).verdict ==
          Verdict::not_finite);
}

TEST_CASE("score_case: closest_hit gives a tie between copies to the first", "[app]") {
    const RayCase copies = make_case(
        {{kSphere, expect_hit(5.0)}, {kSphere, expect_hit(5.0)}, {kPlane, expect_hit(9.0)}});
    CHECK(score(kClosest, copies, closest_answer(0, hit_at(5.0))).verdict == Verdict::pass);
    const Scored last = score(kClosest, copies, closest_answer(1, hit_at(5.0)));
    CHECK(last.verdict == Verdict::wrong_primitive);
    CHECK(last.detail.find("ties go to the first") != std::string::npos);
}

TEST_CASE("score_case: closest_hit gives an exact tie across kinds to spheres, then triangles",
          "[app]") {
    // Hits at exactly t = 5 that no rounding moves (tolerance 0), listed plane first.
    Expectation exact_plane = expect_hit(5.0);
    exact_plane.t_tolerance = 0.0;
    Expectation exact_triangle = expect_triangle_hit(5.0, 0.25, 0.25);
    exact_triangle.t_tolerance = 0.0;
    const RayCase ray_case = make_case({{kPlane, exact_plane}, {kTriangle, exact_triangle}});
    CHECK(score(kClosest, ray_case, closest_answer(1, hit_at(5.0, kUp, 0.25, 0.25))).verdict ==
          Verdict::pass);
    CHECK(score(kClosest, ray_case, closest_answer(0, hit_at(5.0))).verdict ==
          Verdict::wrong_primitive);
    // Where either t may round, the same two hits may go either way.
    const RayCase rounded =
        make_case({{kPlane, expect_hit(5.0)}, {kTriangle, expect_triangle_hit(5.0, 0.25, 0.25)}});
    CHECK(score(kClosest, rounded, closest_answer(0, hit_at(5.0))).verdict == Verdict::pass);
}

TEST_CASE("score_case: closest_hit on a primitive the ray misses is a false hit", "[app]") {
    const RayCase ray_case = make_case({{kSphere, expect_miss()}, {kPlane, expect_hit(15.0)}});
    const Scored scored = score(kClosest, ray_case, closest_answer(0, hit_at(3.0)));
    CHECK(scored.verdict == Verdict::false_hit);
    CHECK(scored.detail == "primitive 0 (sphere): expected a miss, got the closest hit at t = 3");
    // A primitive number from untrusted code that the case does not have.
    CHECK(score(kClosest, ray_case, closest_answer(2, hit_at(15.0))).verdict == Verdict::false_hit);
    CHECK(score(kClosest, ray_case, closest_answer(std::nullopt, hit_at(15.0))).verdict ==
          Verdict::false_hit);
}

TEST_CASE("score_case: closest_hit near a boundary may take either answer", "[app]") {
    // The nearer triangle is near a boundary: skipping it for the plane behind passes, and so
    // does reporting its crossing point, even though the exact answer there is a miss.
    const RayCase ray_case =
        make_case({{kTriangle, near_miss_crossing(5.0)}, {kPlane, expect_hit(15.0)}});
    CHECK(score(kClosest, ray_case, closest_answer(1, hit_at(15.0))).verdict == Verdict::pass);
    CHECK(score(kClosest, ray_case, closest_answer(0, hit_at(5.0, kUp, 1.0, 0.0))).verdict ==
          Verdict::pass);
    // The same for a near-boundary hit: a correct test may miss it, so the plane is no mistake.
    const RayCase near_hit_case =
        make_case({{kTriangle, near_boundary(expect_triangle_hit(5.0, 0.0, 1.0))},
                   {kPlane, expect_hit(15.0)}});
    CHECK(score(kClosest, near_hit_case, closest_answer(1, hit_at(15.0))).verdict == Verdict::pass);

    // Only near-boundary hits: a miss passes, unless the primitives are a closed mesh.
    CHECK(score(kClosest, shared_edge_case(false), closest_answer(std::nullopt, std::nullopt))
              .verdict == Verdict::pass);
    CHECK(score(kClosest, shared_edge_case(true), closest_answer(std::nullopt, std::nullopt))
              .verdict == Verdict::leak);
}

TEST_CASE("score_case: closest_hit may choose either of two hits within rounding of each other",
          "[app]") {
    const RayCase ray_case =
        make_case({{kSphere, expect_hit(5.0)}, {kPlane, expect_hit(5.0 + kTTolerance)}});
    CHECK(score(kClosest, ray_case, closest_answer(1, hit_at(5.0 + kTTolerance))).verdict ==
          Verdict::pass);

    // A sphere whose near root (at t_min) may be skipped for its far root at t = 2 is not clearly
    // nearer than a hit at 1.5.
    Expectation on_surface = expect_hit(0.0);
    on_surface.t_alternative = 2.0;
    on_surface.normal_alternative = {0.0, 0.0, -1.0};
    const RayCase surface_case = make_case({{kSphere, on_surface}, {kPlane, expect_hit(1.5)}});
    CHECK(score(kClosest, surface_case, closest_answer(1, hit_at(1.5))).verdict == Verdict::pass);
}

TEST_CASE("score_family: counts verdicts, keeps the first counterexamples, skips other kinds",
          "[app]") {
    CaseFamily family{"mixed", 7, "", {}};
    std::vector<CaseAnswer> answers;
    for (std::uint64_t k = 0; k < 6; ++k) {
        family.cases.push_back(make_case({{kSphere, expect_hit(5.0)}}, false, k));
        // Cases 1, 3 and 5 miss.
        answers.push_back(answer({k % 2 == 0 ? std::optional<Hit>(hit_at(5.0)) : std::nullopt}));
    }
    family.cases.push_back(make_case({{kPlane, expect_hit(3.0)}}, false, 6));
    answers.push_back(answer({std::nullopt}));
    // One hit a unit in the last place beyond t.
    answers[2].hits[0]->t = std::nextafter(5.0, 6.0);

    const MethodScore scored = score_family(kSphereTest, family, answers, 2);
    CHECK(scored.method == "intersect_sphere");
    CHECK(scored.family == "mixed");
    CHECK(scored.cases == 6);  // the plane's case is not the sphere test's
    CHECK(scored.passed == 3);
    CHECK(scored.count(Verdict::false_miss) == 3);
    CHECK(scored.count(Verdict::pass) == 3);
    CHECK_FALSE(scored.not_implemented);
    REQUIRE(scored.counterexamples.size() == 2);
    CHECK(scored.counterexamples[0].case_index == 1);
    CHECK(scored.counterexamples[1].case_index == 3);
    CHECK(scored.counterexamples[0].verdict == Verdict::false_miss);
    CHECK(scored.counterexamples[0].detail ==
          "primitive 0 (sphere): expected a hit at t = 5, got a miss");
    CHECK(scored.counterexamples[0].text == case_text(family.cases[1]));
    CHECK(scored.t_ulps == std::vector<double>{0.0, 1.0, 0.0});
}

TEST_CASE("score_family: counts near-boundary answers of either kind", "[app]") {
    CaseFamily family{"edges", 1, "", {shared_edge_case(false)}};
    const MethodScore scored =
        score_family(kTriangleTest, family, {answer({hit_at(5.0, kUp, 0.5, 0.5), std::nullopt})});
    CHECK(scored.passed == 1);
    CHECK(scored.near_boundary_hits == 1);
    CHECK(scored.near_boundary_misses == 1);
    CHECK(scored.t_ulps == std::vector<double>{0.0});
}

TEST_CASE("score_family: exact false hits and misses count what near-boundary forgives", "[app]") {
    // A near-boundary miss reported as a hit passes, and is an exact false hit; a near-boundary
    // hit reported as a miss passes, and is an exact false miss. Which neighbour of a shared edge
    // takes the ray is neither.
    CaseFamily family{"edges",
                      1,
                      "",
                      {make_case({{kTriangle, near_miss_crossing(5.0)}}),
                       make_case({{kTriangle, near_boundary(expect_triangle_hit(5.0, 0.0, 0.5))}}),
                       shared_edge_case(true)}};
    const MethodScore scored =
        score_family(kTriangleTest, family,
                     {answer({hit_at(5.0, kUp, 1.0, 0.0)}), answer({std::nullopt}),
                      answer({std::nullopt, hit_at(5.0, kUp, 0.0, 0.5)})});
    CHECK(scored.passed == 3);
    CHECK(scored.exact_false_hits == 1);
    CHECK(scored.exact_false_misses == 1);
}

TEST_CASE("score_family: a hit where the exact answer is a miss adds no t error", "[app]") {
    // The crossing point of a near-boundary miss is checked, but it is not a hit to measure.
    CaseFamily family{"near-misses", 1, "", {make_case({{kTriangle, near_miss_crossing(5.0)}})}};
    const MethodScore scored = score_family(
        kTriangleTest, family, {answer({hit_at(std::nextafter(5.0, 6.0), kUp, 1.0, 0.0)})});
    CHECK(scored.passed == 1);
    CHECK(scored.near_boundary_hits == 1);
    CHECK(scored.t_ulps.empty());
}

TEST_CASE("score_family: a hit expected at t = 0 is measured in t, not in ulps of 0", "[app]") {
    // A ray that starts on the surface: its exact t is 0, and a right answer 1e-17 from it is
    // 4e18 ulps of 0 away. It is counted apart, with its error, so that the ulp figures of a
    // right method stay small; a hit away from 0 is measured in ulps as before.
    CaseFamily family{"origins-on-surface",
                      1,
                      "",
                      {make_case({{kTriangle, expect_triangle_hit(0.0, 0.25, 0.25)}}),
                       make_case({{kTriangle, expect_triangle_hit(5.0, 0.25, 0.25)}})}};
    const MethodScore scored = score_family(
        kTriangleTest, family,
        {answer({hit_at(1e-17, kUp, 0.25, 0.25)}), answer({hit_at(5.0, kUp, 0.25, 0.25)})});
    CHECK(scored.passed == 2);
    CHECK(scored.hits_at_t_zero == 1);
    CHECK(scored.largest_t_error_at_zero == 1e-17);
    CHECK(scored.t_ulps == std::vector<double>{0.0});
}

TEST_CASE("score_family: a stub makes the whole method not implemented", "[app]") {
    CaseFamily family{"stubs", 1, "", {}};
    for (std::uint64_t k = 0; k < 3; ++k) {
        family.cases.push_back(make_case({{kSphere, expect_hit(5.0)}}, false, k));
    }
    CaseAnswer stub;
    stub.not_implemented = true;
    stub.error = "stage 3: intersect_sphere is not implemented yet";
    const MethodScore scored =
        score_family(kSphereTest, family, {answer({std::nullopt}), stub, answer({hit_at(5.0)})});
    CHECK(scored.not_implemented);
    CHECK(scored.not_implemented_message == "stage 3: intersect_sphere is not implemented yet");
    CHECK(scored.cases == 0);
    CHECK(scored.counterexamples.empty());
}

TEST_CASE("score_family: the answers must match the cases one to one", "[app]") {
    CaseFamily family{"one", 1, "", {make_case({{kSphere, expect_hit(5.0)}})}};
    CHECK_THROWS_AS(score_family(kSphereTest, family, {}), std::invalid_argument);
}

TEST_CASE("ulp_distance: counts the doubles between two values", "[app]") {
    CHECK(ulp_distance(1.0, 1.0) == 0.0);
    CHECK(ulp_distance(1.0, std::nextafter(1.0, 2.0)) == 1.0);
    CHECK(ulp_distance(std::nextafter(1.0, 0.0), std::nextafter(1.0, 2.0)) == 2.0);
    CHECK(ulp_distance(-0.0, 0.0) == 0.0);
    const double tiny = std::numeric_limits<double>::denorm_min();
    CHECK(ulp_distance(-tiny, tiny) == 2.0);
    // 1.0 is 0x3ff0000000000000 doubles above zero, and -1.0 as many below.
    CHECK(ulp_distance(1.0, -1.0) == 2.0 * 0x3ff0000000000000);
    CHECK(ulp_distance(-1.0, 1.0) == ulp_distance(1.0, -1.0));
    // From -max to +max is beyond INT64_MAX and must not overflow.
    const double max = std::numeric_limits<double>::max();
    CHECK(ulp_distance(-max, max) == 2.0 * 0x7fefffffffffffff);
    CHECK(ulp_distance(max, std::numeric_limits<double>::infinity()) == 1.0);
    CHECK(std::isinf(ulp_distance(kNaN, 1.0)));
    CHECK(std::isinf(ulp_distance(1.0, kNaN)));
}

TEST_CASE("verdict_name: every verdict has its own name", "[app]") {
    std::vector<std::string> names;
    for (int v = 0; v < kVerdictCount; ++v) {
        CAPTURE(v);
        const std::string name = verdict_name(static_cast<Verdict>(v));
        CHECK(std::find(names.begin(), names.end(), name) == names.end());
        names.push_back(name);
    }
    CHECK(std::string(verdict_name(Verdict::false_miss)) == "false miss");
    CHECK(std::string(verdict_name(Verdict::wrong_barycentrics)) == "wrong barycentrics");
}
