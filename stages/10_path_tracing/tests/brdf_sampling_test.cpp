// Public tests for stage 10, importance sampling the BRDF. sample_brdf's directions are held to
// brdf_pdf by the chi-square test of direction_test.h, and brdf_pdf to the contract's mixture,
// worked here by hand, which must integrate to 1.

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/uses.h"
#include "stages/10_path_tracing/path_tracing.h"
#include "stages/10_path_tracing/tests/direction_test.h"

using namespace raystep;
using raystep::testing::direction_chi_square;
using raystep::testing::IsNear;
using raystep::testing::kSignificance;
using raystep::testing::sphere_integral;
using raystep::testing::uses;

namespace {

constexpr double kPi = glm::pi<double>();

SurfaceBrdf phong(Color kd, Color ks, double s) {
    return {BrdfModel::phong, kd, ks, s, 0.0};
}
SurfaceBrdf ggx(Color kd, Color ks, double alpha) {
    return {BrdfModel::ggx, kd, ks, 0.0, alpha};
}

// A tilted normal and a view off it, so that no lobe lines up with the test's bins.
const Vec3 kNormal = glm::normalize(Vec3(0.2, -0.3, 0.9));
const Vec3 kToEye = glm::normalize(Vec3(0.7, 0.1, 0.6));

}  // namespace

TEST_CASE("specular_probability: Ks's share of Kd + Ks, at least 0.25 for GGX", "[stage10]") {
    CHECK_THAT(specular_probability(phong(Color(0.6), Color(0.2), 10.0)), IsNear(0.25, 1e-15));
    CHECK_THAT(specular_probability(phong({0.3, 0.6, 0.9}, {0.0, 0.0, 0.6}, 10.0)),
               IsNear(0.2 / 0.8, 1e-15));
    CHECK(specular_probability(phong(Color(0.5), Color(0.0), 10.0)) == 0.0);
    CHECK(specular_probability(phong(Color(0.0), Color(0.5), 10.0)) == 1.0);
    CHECK(specular_probability(phong(Color(0.0), Color(0.0), 10.0)) == 0.0);
    CHECK_THAT(specular_probability(ggx(Color(0.9), Color(0.1), 0.3)), IsNear(0.25, 1e-15));
    CHECK_THAT(specular_probability(ggx(Color(0.2), Color(0.6), 0.3)), IsNear(0.75, 1e-15));
}

TEST_CASE("brdf_pdf: the diffuse and specular lobes' densities, mixed by t", "[stage10]") {
    INFO(uses("brdf_pdf", "specular_probability, frame_around and the lobes' _pdf functions"));
    const Vec3 n{0.0, 0.0, 1.0};
    const Vec3 wo{0.6, 0.0, 0.8};
    const Vec3 mirror{-0.6, 0.0, 0.8};
    // Phong, t = 0.5, at the mirror direction: 0.5 cos / pi + 0.5 (s + 1) / (2 pi).
    CHECK_THAT(brdf_pdf(phong(Color(0.5), Color(0.5), 10.0), n, wo, mirror),
               IsNear(0.5 * 0.8 / kPi + 0.5 * 11.0 / (2.0 * kPi), 1e-14));
    // GGX, t = 0.25, at the mirror direction: h = n, D cos / (4 wi . h) = 1 / (pi alpha^2 3.2).
    CHECK_THAT(brdf_pdf(ggx(Color(0.75), Color(0.0), 0.5), n, wo, mirror),
               IsNear(0.75 * 0.8 / kPi + 0.25 / (kPi * 0.25 * 3.2), 1e-14));
    // Below the surface the diffuse lobe has no density.
    CHECK(brdf_pdf(phong(Color(0.5), Color(0.0), 10.0), n, wo, {0.0, 0.6, -0.8}) == 0.0);
}

TEST_CASE("brdf_pdf: integrates to 1 over the sphere for Phong and GGX", "[stage10]") {
    for (const SurfaceBrdf& brdf :
         {phong(Color(0.5), Color(0.5), 1.0), phong(Color(0.2), Color(0.6), 8.0),
          ggx(Color(0.5), Color(0.5), 0.6), ggx(Color(0.1), Color(0.9), 0.3)}) {
        CAPTURE(static_cast<int>(brdf.model), brdf.shininess, brdf.roughness);
        const auto pdf = [&](const Vec3& wi) { return brdf_pdf(brdf, kNormal, kToEye, wi); };
        CHECK_THAT(sphere_integral(pdf, 4000, 800), IsNear(1.0, 1e-3));
    }
}

TEST_CASE("sample_brdf: its directions pass the chi-square test against brdf_pdf", "[stage10]") {
    INFO(uses("sample_brdf", "brdf_pdf, cosine_hemisphere, phong_lobe and ggx_half_vector"));
    std::uint64_t seed = 20;
    for (const SurfaceBrdf& brdf :
         {phong(Color(0.5), Color(0.0), 5.0), phong(Color(0.2), Color(0.6), 8.0),
          ggx(Color(0.5), Color(0.5), 0.6), ggx(Color(0.1), Color(0.9), 0.3)}) {
        CAPTURE(static_cast<int>(brdf.model), brdf.shininess, brdf.roughness);
        // The lobe's choice from a stream of its own, so that u stays the test's.
        RandomStream choices(seed, 1);
        const auto result = direction_chi_square(
            [&](const Vec2& u) { return sample_brdf(brdf, kNormal, kToEye, u, choices.next()); },
            [&](const Vec3& wi) { return brdf_pdf(brdf, kNormal, kToEye, wi); }, seed++);
        INFO(result.problem);
        REQUIRE(result.problem.empty());
        CHECK(result.p_value > kSignificance);
    }
}
