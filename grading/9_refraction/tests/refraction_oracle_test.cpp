// Tests of stage 9's long-double oracle (grading/9_refraction/refraction_oracle.h): hand-worked
// answers, the critical angle's band, the fake scenes' recursion, and its rounding budget against
// right formulas in double (the reference's, and the trigonometric and Cook-Torrance forms the
// corpus's alternatives use) on 100 seeds of random cases.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/geometric.hpp>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "base/testing/special_values.h"
#include "grader/oracle/tests/wide_near.h"
#include "grading/9_refraction/refraction_oracle.h"
#include "stages/9_refraction/refraction.h"

using namespace raystep;

namespace {

using raystep::testing::kInf;
using raystep::testing::wide_near;

// The largest component of |got - expected| over the tolerance: at most 1 for a right answer.
double error_ratio(const Vec3& got, const ExpectedRefraction& e) {
    double worst = 0;
    for (int k = 0; k < 3; ++k)
        worst =
            std::max(worst, static_cast<double>(std::abs(got[k] - e.direction[k]) / e.tolerance));
    return worst;
}

// Snell by angles, another right formula in double (the corpus's 9-snell-by-angles).
std::optional<Vec3> refract_by_angles(const Vec3& incident, const Vec3& normal, double eta) {
    const double cos1 = -glm::dot(incident, normal);
    const Vec3 along = incident + cos1 * normal;
    const double sin1 = glm::length(along);
    if (sin1 == 0.0) return -normal;
    const double sin2 = eta * std::sin(std::atan2(sin1, cos1));
    if (sin2 > 1.0) return std::nullopt;
    const double theta2 = std::asin(sin2);
    return std::sin(theta2) * (along / sin1) - std::cos(theta2) * normal;
}

// The exact Fresnel reflectance in Cook and Torrance's form (the corpus's alternative).
double fresnel_cook_torrance(double c, double n1, double n2) {
    const double ratio = n2 / n1;
    const double g_squared = ratio * ratio - 1.0 + c * c;
    if (g_squared <= 0.0) return 1.0;
    const double g = std::sqrt(g_squared);
    const double a = (g - c) / (g + c);
    const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

// The exact Fresnel reflectance in its sine-and-tangent form, r_s = -sin(theta1 - theta2) /
// sin(theta1 + theta2) and r_p = tan(theta1 - theta2) / tan(theta1 + theta2), with sin(theta1)
// taken as sqrt(1 - c^2) for Snell's law and theta1 as acos(c) (the corpus's
// 9-fresnel-by-sines-and-tangents) or, with `theta1_by_asin`, as asin(sin(theta1)).
double fresnel_sines_and_tangents(double c, double n1, double n2, bool theta1_by_asin) {
    const double cos1 = std::min(c, 1.0);
    const double sin1 = std::sqrt(1.0 - cos1 * cos1);
    const double sin2 = n1 / n2 * sin1;
    if (sin2 >= 1.0) return 1.0;
    const double theta1 = theta1_by_asin ? std::asin(sin1) : std::acos(cos1);
    const double theta2 = std::asin(sin2);
    if (theta1 == 0.0) {
        const double r0 = (n1 - n2) / (n1 + n2);
        return r0 * r0;
    }
    const double r_s = -std::sin(theta1 - theta2) / std::sin(theta1 + theta2);
    const double r_p = std::tan(theta1 - theta2) / std::tan(theta1 + theta2);
    return (r_s * r_s + r_p * r_p) / 2;
}

// A cosine for Fresnel: uniform, or within 1e-16 to 0.1 of 1 (head-on) or of 0 (grazing), where
// the forms part ways.
double random_cosine(PortableRandom& random, int k) {
    switch (k % 3) {
        case 0:
            return random.unit();
        case 1:
            return 1.0 - random.decade(-16, -1);
        default:
            return random.decade(-16, -1);
    }
}

// The right Fresnel forms' answers at (c, n1, n2).
std::vector<double> right_fresnel_forms(double c, double n1, double n2) {
    return {fresnel_exact(c, n1, n2), fresnel_cook_torrance(c, n1, n2),
            fresnel_sines_and_tangents(c, n1, n2, false),
            fresnel_sines_and_tangents(c, n1, n2, true)};
}

// A random refraction: a unit normal anywhere, an incident direction on its side, and eta near
// 1, far from it, or (every fourth case) within 1e-12 of the critical angle.
struct RandomRefraction {
    Vec3 incident;
    Vec3 normal;
    double eta;
};

RandomRefraction random_refraction(PortableRandom& random, int k) {
    RandomRefraction r;
    r.normal = random.unit_vector();
    r.eta = k % 2 == 0 ? random.uniform(0.6, 1.7) : random.decade(-1, 1);
    if (k % 4 == 3 && r.eta > 1) {
        const double sin1 = std::min(1.0, (1 / r.eta) * (1 + random.uniform(-1e-12, 1e-12)));
        Vec3 along = random.unit_vector();
        along = glm::normalize(along - glm::dot(along, r.normal) * r.normal);
        r.incident = glm::normalize(sin1 * along - std::sqrt(1 - sin1 * sin1) * r.normal);
        return r;
    }
    r.incident = random.unit_vector();
    if (glm::dot(r.incident, r.normal) > 0) r.incident = -r.incident;
    return r;
}

// Whether a right formula's answer is one the oracle accepts.
bool accepted(const std::optional<Vec3>& got, const ExpectedRefraction& e) {
    if (!got) return e.answer != RefractionAnswer::direction;
    return e.answer != RefractionAnswer::none && wide_near(e.direction, *got, e.tolerance);
}

}  // namespace

TEST_CASE("expected_refraction: 45 degrees into glass bends to asin(sin 45 / 1.5)", "[grader]") {
    const Vec3 incident = glm::normalize(Vec3{1, -1, 0});
    const ExpectedRefraction e = expected_refraction(incident, {0, 1, 0}, 1 / 1.5);
    REQUIRE(e.answer == RefractionAnswer::direction);
    const double sin2 = std::sqrt(0.5) / 1.5;
    CHECK(wide_near(e.direction, {sin2, -std::sqrt(1 - sin2 * sin2), 0}, 1e-15L));
    CHECK(e.tolerance < 1e-13L);
}

TEST_CASE("expected_refraction: at and one ulp either side of the critical angle takes either",
          "[grader]") {
    const double sin_c = 1 / 1.5;
    const Vec3 critical{sin_c, -std::sqrt(1 - sin_c * sin_c), 0};
    for (const double x :
         {critical.x, std::nextafter(critical.x, 1.0), std::nextafter(critical.x, 0.0)}) {
        CAPTURE(x);
        CHECK(expected_refraction({x, critical.y, 0}, {0, 1, 0}, 1.5).answer ==
              RefractionAnswer::either);
    }
    // A millionth of a degree beyond it, and before it, the answer is decided.
    const double beyond = std::asin(sin_c) + 1e-8;
    CHECK(expected_refraction({std::sin(beyond), -std::cos(beyond), 0}, {0, 1, 0}, 1.5).answer ==
          RefractionAnswer::none);
    const double before = std::asin(sin_c) - 1e-8;
    CHECK(expected_refraction({std::sin(before), -std::cos(before), 0}, {0, 1, 0}, 1.5).answer ==
          RefractionAnswer::direction);
}

TEST_CASE("expected_fresnel_exact: 4% head-on, 25/338 at Brewster's angle, 1 beyond critical",
          "[grader]") {
    const ExpectedNumber head_on = expected_fresnel_exact(1.0, 1.0, 1.5);
    CHECK(std::abs(head_on.value - 0.04L) < 1e-18L);
    // At Brewster's angle the p reflectance vanishes: F = r_s^2 / 2 = (5/13)^2 / 2.
    const ExpectedNumber brewster = expected_fresnel_exact(1 / std::sqrt(3.25), 1.0, 1.5);
    CHECK(std::abs(brewster.value - 25.0L / 338) < 1e-16L);
    const ExpectedNumber beyond = expected_fresnel_exact(0.5, 1.5, 1.0);
    CHECK(beyond.value == 1);
    CHECK(beyond.tolerance < 1e-14L);
}

TEST_CASE("expected_fresnel_schlick: leaving glass uses the cosine outside", "[grader]") {
    // Leaving glass at 30 degrees: sin(theta2) = 0.75, so (1 - cos)^5 with cos = sqrt(7) / 4.
    const ExpectedNumber leaving = expected_fresnel_schlick(std::sqrt(3.0) / 2, 1.5, 1.0);
    const Wide m = 1 - std::sqrt(7.0L) / 4;
    CHECK(std::abs(leaving.value - (0.04L + 0.96L * m * m * m * m * m)) < 1e-15L);
    CHECK(expected_fresnel_schlick(0.5, 1.5, 1.0).value == 1);
}

TEST_CASE("expected_after_crossing: leaving takes the solid from wherever it is", "[grader]") {
    const Medium glass{1, 1.5};
    const Medium water{2, 1.33};
    CHECK(expected_after_crossing({glass, water}, glass, false) == MediumStack{water});
    CHECK(expected_after_crossing({water}, glass, false) == MediumStack{water});
    CHECK(expected_after_crossing({glass, glass}, glass, false) == MediumStack{glass});
    CHECK(expected_current_index({}) == 1.0);
    CHECK(expected_current_index({water, glass}) == 1.5);
}

TEST_CASE(
    "expected_radiance_with_refraction: head-on glass adds 4% of the reflected ray and 96% of "
    "the refracted one",
    "[grader]") {
    const SurfacePoint point{{40, 0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    int asked = 0;
    const HitMaker make = [&](const Ray&, const MediumStack& inside) -> std::optional<MediumHit> {
        ++asked;
        if (asked == 1) return MediumHit{{point, Color(0.1), Color(0)}, Color(1), {1, 1.5}, true};
        // The reflected ray stays in air, the refracted one is in the glass.
        const Color local = inside.empty() ? Color(1, 0, 0) : Color(0, 0, 1);
        SurfacePoint far = point;
        far.position.x = 40.0 * asked;
        return MediumHit{{far, local, Color(0)}, Color(0), {1, 1.5}, true};
    };
    const ExpectedRefractionRadiance e = expected_radiance_with_refraction(
        make, {{0, 0, 0}, {1, 0, 0}, 0, kInf}, 1, {}, false, {OffsetRule::along_ray, 1e-4});
    CHECK(wide_near(e.colour, {0.14, 0.1, 1.06}, 1e-15L));
    CHECK(e.rays.size() == 3);
    CHECK(e.scene.size() == 3);
    CHECK(e.colour_tolerance.z < 1e-14L);
}

TEST_CASE("expected_radiance_with_refraction: refuses a hit on the critical angle", "[grader]") {
    const double sin_c = 1 / 1.5;
    const SurfacePoint point{
        {40, 0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 1, 0}, {sin_c, std::sqrt(1 - sin_c * sin_c), 0}};
    const HitMaker make = [&](const Ray&, const MediumStack&) -> std::optional<MediumHit> {
        return MediumHit{{point, Color(0), Color(0)}, Color(1), {1, 1.5}, false};
    };
    CHECK_THROWS_AS(
        expected_radiance_with_refraction(make, {{0, 0, 0}, {1, 0, 0}, 0, kInf}, 1, {{1, 1.5}},
                                          false, {OffsetRule::along_ray, 1e-4}),
        std::logic_error);
}

TEST_CASE("refraction budget: right formulas in double stay within it on 100 seeds", "[grader]") {
    for (std::uint64_t seed = 1; seed <= 100; ++seed) {
        for (int k = 0; k < 200; ++k) {
            CAPTURE(seed, k);
            PortableRandom random(seed, k);
            const RandomRefraction r = random_refraction(random, k);
            const ExpectedRefraction e = expected_refraction(r.incident, r.normal, r.eta);
            CHECK(accepted(refract(r.incident, r.normal, r.eta), e));
            CHECK(accepted(refract_by_angles(r.incident, r.normal, r.eta), e));
            const double c = random_cosine(random, k);
            const double n1 = random.uniform(1, 3);
            const double n2 = random.uniform(1, 3);
            const ExpectedNumber f = expected_fresnel_exact(c, n1, n2);
            for (const double got : right_fresnel_forms(c, n1, n2))
                CHECK(std::abs(got - f.value) <= f.tolerance);
            const ExpectedNumber s = expected_fresnel_schlick(c, n1, n2);
            CHECK(std::abs(fresnel_schlick(c, n1, n2) - s.value) <= s.tolerance);
        }
    }
}

TEST_CASE(
    "refraction budget: the sine-and-tangent form, 2.5e-15 off at fresnel_exact(0.999, 2.4, 1), "
    "is within it",
    "[grader]") {
    // Issue 36: a tolerance of the cosine form's rounding alone, 1.8e-15 here, failed it.
    const ExpectedNumber f = expected_fresnel_exact(0.999, 2.4, 1.0);
    const double got = fresnel_sines_and_tangents(0.999, 2.4, 1.0, false);
    CHECK(std::abs(got - f.value) > 2e-15L);
    CHECK(std::abs(got - f.value) <= f.tolerance);
    // Near head-on its two angles part by up to 2^-28 of theta: 4e-10 in F.
    const double near_head_on = 1.0 - 0x1p-27;
    const ExpectedNumber g = expected_fresnel_exact(near_head_on, 2.4, 1.0);
    CHECK(std::abs(fresnel_sines_and_tangents(near_head_on, 2.4, 1.0, false) - g.value) <=
          g.tolerance);
    // Still far below the error of a wrong formula: Schlick's, say, is 1e-3 off here.
    CHECK(g.tolerance < 1e-8L);
}

TEST_CASE("refraction budget: how close right formulas come to it", "[.][measure]") {
    // Hidden: it prints the figures of docs/measurements/stage9-checks.md, which the test above
    // already holds to 1; run it by name to measure them again.
    double worst_reference = 0;
    double worst_angles = 0;
    double worst_fresnel = 0;
    double worst_cook_torrance = 0;
    double worst_sines = 0;
    int either = 0;
    int cases = 0;
    for (std::uint64_t seed = 1; seed <= 100; ++seed) {
        for (int k = 0; k < 200; ++k) {
            PortableRandom random(seed, k);
            const RandomRefraction r = random_refraction(random, k);
            const ExpectedRefraction e = expected_refraction(r.incident, r.normal, r.eta);
            ++cases;
            if (e.answer == RefractionAnswer::either) ++either;
            if (const auto got = refract(r.incident, r.normal, r.eta))
                worst_reference = std::max(worst_reference, error_ratio(*got, e));
            if (const auto got = refract_by_angles(r.incident, r.normal, r.eta))
                worst_angles = std::max(worst_angles, error_ratio(*got, e));
            const double c = random_cosine(random, k);
            const double n1 = random.uniform(1, 3);
            const double n2 = random.uniform(1, 3);
            const ExpectedNumber f = expected_fresnel_exact(c, n1, n2);
            for (const bool by_asin : {false, true}) {
                worst_sines = std::max(
                    worst_sines,
                    static_cast<double>(
                        std::abs(fresnel_sines_and_tangents(c, n1, n2, by_asin) - f.value) /
                        f.tolerance));
            }
            worst_fresnel = std::max(
                worst_fresnel,
                static_cast<double>(std::abs(fresnel_exact(c, n1, n2) - f.value) / f.tolerance));
            worst_cook_torrance =
                std::max(worst_cook_torrance,
                         static_cast<double>(std::abs(fresnel_cook_torrance(c, n1, n2) - f.value) /
                                             f.tolerance));
        }
    }
    std::printf("cases %d, within rounding of the critical angle %d\n", cases, either);
    std::printf("refract, largest error over tolerance: reference %.3g, by angles %.3g\n",
                worst_reference, worst_angles);
    std::printf(
        "fresnel_exact, largest error over tolerance: reference %.3g, Cook-Torrance %.3g, sines "
        "and tangents %.3g\n",
        worst_fresnel, worst_cook_torrance, worst_sines);
    CHECK(std::max({worst_reference, worst_angles, worst_fresnel, worst_cook_torrance,
                    worst_sines}) <= 1);
}
