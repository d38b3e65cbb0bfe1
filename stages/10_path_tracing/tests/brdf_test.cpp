// Public tests for stage 10, the Phong and GGX BRDFs. Each value is worked by hand from the
// contract's formula, and the lobes are held to what any BRDF must do: zero below the surface,
// the same with wi and wo swapped, and reflecting no more than arrives.

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/vec3_matchers.h"
#include "stages/10_path_tracing/path_tracing.h"
#include "stages/10_path_tracing/tests/direction_test.h"

using namespace raystep;
using raystep::testing::IsNear;
using raystep::testing::sphere_integral;

namespace {

constexpr double kPi = glm::pi<double>();
const Vec3 kUp{0.0, 0.0, 1.0};

SurfaceBrdf phong(Color kd, Color ks, double s) {
    return {BrdfModel::phong, kd, ks, s, 0.0};
}
SurfaceBrdf ggx(Color kd, Color ks, double alpha) {
    return {BrdfModel::ggx, kd, ks, 0.0, alpha};
}

// The hemisphere's albedo for light arriving from `to_eye`: the integral of f cos over wi.
double albedo(const SurfaceBrdf& brdf, const Vec3& to_eye) {
    return sphere_integral(
        [&](const Vec3& wi) {
            return evaluate_brdf(brdf, kUp, wi, to_eye).x * std::max(wi.z, 0.0);
        },
        4000, 800);
}

}  // namespace

TEST_CASE("evaluate_brdf: a diffuse surface is Kd / pi wherever wi and wo are above it",
          "[stage10]") {
    const SurfaceBrdf brdf = phong({0.5, 0.25, 1.0}, Color(0.0), 10.0);
    const Vec3 wo = glm::normalize(Vec3(1.0, 0.0, 1.0));
    CHECK_THAT(evaluate_brdf(brdf, kUp, kUp, wo), IsNear(Color(0.5, 0.25, 1.0) / kPi, 1e-15));
    CHECK(evaluate_brdf(brdf, kUp, {0.6, 0.0, -0.8}, wo) == Color(0.0));
    CHECK(evaluate_brdf(brdf, kUp, kUp, {0.6, 0.0, -0.8}) == Color(0.0));
    CHECK(evaluate_brdf(brdf, kUp, {1.0, 0.0, 0.0}, wo) == Color(0.0));
}

TEST_CASE("evaluate_brdf: the Phong lobe is Ks (s + 2) / (2 pi) at the mirror direction",
          "[stage10]") {
    const SurfaceBrdf brdf = phong(Color(0.0), Color(0.5), 20.0);
    const Vec3 wo{0.6, 0.0, 0.8};
    const Vec3 mirror{-0.6, 0.0, 0.8};
    CHECK_THAT(evaluate_brdf(brdf, kUp, mirror, wo),
               IsNear(Color(0.5 * 22.0 / (2.0 * kPi)), 1e-14));
    // At 0.8 = cos(alpha) from the mirror direction: cos^20.
    const Vec3 off = glm::normalize(Vec3(-0.6, 0.0, 0.8) * 0.8 + Vec3(0.0, 0.6, 0.0));
    const double cos_alpha = glm::dot(off, mirror);
    CHECK_THAT(evaluate_brdf(brdf, kUp, off, wo),
               IsNear(Color(0.5 * 22.0 / (2.0 * kPi) * std::pow(cos_alpha, 20.0)), 1e-13));
}

TEST_CASE("evaluate_brdf: the Phong lobe reflects all that arrives along the normal, Ks 1",
          "[stage10]") {
    // With wo = n the mirror direction is n, and (s + 2) / (2 pi) cos^(s + 1) integrates to 1.
    for (double s : {1.0, 10.0, 50.0}) {
        CAPTURE(s);
        CHECK_THAT(albedo(phong(Color(0.0), Color(1.0), s), kUp), IsNear(1.0, 1e-4));
    }
}

TEST_CASE("evaluate_brdf: GGX along the normal is Kd / pi + Ks / (4 pi alpha^2)", "[stage10]") {
    // wi = wo = n: h = n, F = Ks, G = 1, D = 1 / (pi alpha^2), 4 cos cos = 4.
    const SurfaceBrdf brdf = ggx(Color(0.2), Color(0.04, 0.5, 1.0), 0.3);
    const Color expected = Color(0.2) / kPi + Color(0.04, 0.5, 1.0) / (4.0 * kPi * 0.09);
    CHECK_THAT(evaluate_brdf(brdf, kUp, kUp, kUp), IsNear(expected, 1e-14));
}

TEST_CASE("evaluate_brdf: GGX at 60 degrees, with Schlick's F and Smith's G", "[stage10]") {
    // wo at 60 degrees, wi its mirror image: h = n, D = 1 / (pi alpha^2), F = Ks + (1 - Ks)
    // (1 - cos 60)^5, G1 = 2 / (1 + sqrt(1 + alpha^2 tan^2 60)) for each, 4 cos cos = 1.
    const double alpha = 0.5;
    const Vec3 wo{std::sqrt(0.75), 0.0, 0.5};
    const Vec3 wi{-std::sqrt(0.75), 0.0, 0.5};
    const double d = 1.0 / (kPi * alpha * alpha);
    const double f = 0.1 + 0.9 * std::pow(0.5, 5.0);
    const double g1 = 2.0 / (1.0 + std::sqrt(1.0 + alpha * alpha * 3.0));
    const SurfaceBrdf brdf = ggx(Color(0.0), Color(0.1), alpha);
    CHECK_THAT(evaluate_brdf(brdf, kUp, wi, wo), IsNear(Color(f * g1 * g1 * d), 1e-13));
}

TEST_CASE("evaluate_brdf: both lobes are the same with wi and wo swapped", "[stage10]") {
    const Vec3 a = glm::normalize(Vec3(0.3, -0.2, 0.9));
    const Vec3 b = glm::normalize(Vec3(-0.5, 0.1, 0.4));
    for (const SurfaceBrdf& brdf :
         {phong(Color(0.3), Color(0.6), 8.0), ggx(Color(0.3), Color(0.6), 0.4)}) {
        CAPTURE(static_cast<int>(brdf.model));
        CHECK_THAT(evaluate_brdf(brdf, kUp, a, b), IsNear(evaluate_brdf(brdf, kUp, b, a), 1e-14));
    }
}

TEST_CASE("evaluate_brdf: GGX with Ks 1 reflects no more than arrives, from any angle",
          "[stage10]") {
    for (double alpha : {0.1, 0.5, 1.0}) {
        for (double cos_o : {1.0, 0.7, 0.3}) {
            CAPTURE(alpha, cos_o);
            const Vec3 wo{std::sqrt(1.0 - cos_o * cos_o), 0.0, cos_o};
            const double reflected = albedo(ggx(Color(0.0), Color(1.0), alpha), wo);
            CHECK(reflected <= 1.0);
            // Smith's G loses what would scatter twice: along the normal, 0.69 of it at alpha 1,
            // 0.012 at 0.1 (integrated separately).
            CHECK(reflected > (alpha < 0.2 ? 0.9 : 0.3));
        }
    }
}

TEST_CASE("evaluate_brdf: the Phong lobe is 0 where r . wi <= 0, even at shininess 0",
          "[stage10]") {
    // pow(0, 0) is 1: a lobe of s = 0 must still end at its equator, where its sampler does.
    const Vec3 wo{0.6, 0.0, 0.8};
    const SurfaceBrdf flat = phong(Color(0.0), Color(0.5), 0.0);
    // r = (-0.6, 0, 0.8); (0.8, 0, 0.6) is above the surface and at 90 degrees to r.
    CHECK(evaluate_brdf(flat, kUp, {0.8, 0.0, 0.6}, wo) == Color(0.0));
    CHECK(evaluate_brdf(flat, kUp, glm::normalize(Vec3(0.9, 0.0, 0.3)), wo) == Color(0.0));
    CHECK_THAT(evaluate_brdf(flat, kUp, kUp, wo), IsNear(Color(0.5 * 2.0 / (2.0 * kPi)), 1e-15));
}

TEST_CASE("evaluate_brdf: a Phong lobe of shininess 1e17 stays finite at the mirror direction",
          "[stage10]") {
    // Rounding can put r . wi a hair above 1, and (1 + 1e-16)^(1e17) is e^10: clamp it to 1.
    const Vec3 wo = glm::normalize(Vec3(0.3, -0.2, 0.9));
    const Vec3 mirror = glm::reflect(-wo, kUp);
    for (double s : {1e17, 1e50, 1e100}) {
        CAPTURE(s);
        const Color f = evaluate_brdf(phong(Color(0.0), Color(0.5), s), kUp, mirror, wo);
        CHECK(std::isfinite(f.x));
        CHECK(f.x <= 0.5 * (s + 2.0) / (2.0 * kPi) * (1.0 + 1e-12));
    }
}
