// Tests of stage 10's long-double oracle (grading/10_path_tracing/path_tracing_oracle.h): the
// closed forms the paths are held to against hand-worked values, the floor's quadrature against
// Lambert's form factor, and the formulas against the reference's in double on random cases,
// within the tolerance the checks give a right answer.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "grading/10_path_tracing/path_tracing_oracle.h"
#include "stages/10_path_tracing/path_tracing.h"

using namespace raystep;
using namespace raystep::grade;

namespace {

constexpr double kOraclePi = 3.14159265358979323846;

// A 2 x 2 light at height 1 over the origin, facing down.
const QuadLight kOverheadLight{{-1, -1, 1}, {2, 0, 0}, {0, 2, 0}, {1, 1, 1}, 0};

bool within_path_tolerance(double got, double expected) {
    return std::abs(got - expected) <= path_tolerance(expected);
}

}  // namespace

TEST_CASE("form_factor: a square centred over the point is four corner rectangles") {
    // A 1 x 1 rectangle at height 1 with a corner over the point: (1 / pi) (1 / sqrt 2)
    // atan(1 / sqrt 2).
    const double corner = std::atan(1 / std::sqrt(2.0)) / (std::sqrt(2.0) * kOraclePi);
    CHECK(std::abs(form_factor({0, 0, 0}, {0, 0, 1}, kOverheadLight) - 4 * corner) < 1e-15);
}

TEST_CASE("floor_radiance: a diffuse floor's is Kd L_e F, the quadrature within 1e-9") {
    const SurfaceBrdf diffuse{BrdfModel::phong, {0.6, 0.5, 0.4}, Color(0.0), 0, 0};
    for (const Vec3& point : {Vec3{0, 0, 0}, Vec3{0.7, -0.4, 0}, Vec3{2, 1, 0}}) {
        CAPTURE(point.x, point.y);
        const double f = form_factor(point, {0, 0, 1}, kOverheadLight);
        const Color got = floor_radiance(diffuse, point, {0, 0, 1},
                                         glm::normalize(Vec3{0.3, 0.2, 1}), kOverheadLight);
        for (int c = 0; c < 3; ++c)
            CHECK(std::abs(got[c] - diffuse.diffuse[c] * f) <= 1e-9 * got[c]);
    }
}

TEST_CASE("floor_radiance: black where the light shows the point its back") {
    const SurfaceBrdf diffuse{BrdfModel::phong, Color(0.5), Color(0.0), 0, 0};
    const QuadLight facing_up{{-1, -1, 1}, {0, 2, 0}, {2, 0, 0}, {1, 1, 1}, 0};
    CHECK(floor_radiance(diffuse, {0, 0, 0}, {0, 0, 1}, {0, 0, 1}, facing_up) == Color(0.0));
}

TEST_CASE("furnace_radiance: 1 + a + ... + a^d, and L_e / (1 - a) without a limit") {
    CHECK(furnace_radiance(Color(1.0), Color(0.5), 3) == Color(1.875));
    CHECK(furnace_radiance(Color(2.0), Color(0.5), -1) == Color(4.0));
    CHECK(furnace_radiance(Color(1.0), Color(0.5), 0) == Color(1.0));
}

TEST_CASE("the oracle agrees with the reference in double, within the checks' tolerance") {
    for (std::uint64_t k = 0; k < 2000; ++k) {
        PortableRandom random(1010, k);
        CAPTURE(k);
        const Vec3 n = random.unit_vector();
        Vec3 wo = random.unit_vector();
        if (glm::dot(wo, n) < 0.05) wo = glm::normalize(wo + 2.0 * n);
        const Vec3 wi = random.unit_vector();
        const Vec3 r = 2 * glm::dot(n, wo) * n - wo;
        if (std::abs(glm::dot(n, wi)) < 0.05 || std::abs(glm::dot(r, wi)) < 0.05) continue;
        const Color kd{random.unit() * 0.5, random.unit() * 0.5, random.unit() * 0.5};
        const Color ks{random.unit() * 0.5, random.unit() * 0.5, random.unit() * 0.5};
        const SurfaceBrdf brdf =
            k % 2 == 0 ? SurfaceBrdf{BrdfModel::phong, kd, ks, random.decade(0, 2.4), 0}
                       : SurfaceBrdf{BrdfModel::ggx, kd, ks, 0, random.uniform(0.05, 1)};
        const Color e = expected_brdf(brdf, n, wi, wo);
        const Color got = evaluate_brdf(brdf, n, wi, wo);
        const double size = std::max({e.x, e.y, e.z});
        for (int c = 0; c < 3; ++c)
            CHECK(std::abs(got[c] - e[c]) <= path_tolerance(size));
        CHECK(within_path_tolerance(brdf_pdf(brdf, n, wo, wi), expected_brdf_pdf(brdf, n, wo, wi)));
        CHECK(
            within_path_tolerance(specular_probability(brdf), expected_specular_probability(brdf)));

        const Vec3 d = random.unit_vector();
        const double s = random.decade(-1, 2.4);
        const double alpha = random.uniform(0.02, 1);
        if (std::abs(d.z) > 1e-3) {
            CHECK(within_path_tolerance(phong_lobe_pdf(d, s), expected_phong_lobe_pdf(d, s)));
            CHECK(within_path_tolerance(ggx_distribution(d, alpha),
                                        expected_ggx_distribution(d, alpha)));
            CHECK(
                within_path_tolerance(cosine_hemisphere_pdf(d), expected_cosine_hemisphere_pdf(d)));
        }
        const Vec2 u{random.unit(), random.unit()};
        CHECK(glm::length(phong_lobe(u, s) - expected_phong_lobe(u, s)) < 1e-12);
        CHECK(glm::length(ggx_half_vector(u, alpha) - expected_ggx_half_vector(u, alpha)) < 1e-12);
        CHECK(glm::length(cosine_hemisphere(u) - expected_cosine_hemisphere(u)) < 1e-12);

        const QuadLight light{random.unit_vector(),
                              random.unit_vector(),
                              glm::normalize(glm::cross(random.unit_vector(), n)),
                              {1, 2, 3},
                              0};
        const Vec3 point = random.unit_vector() * 3.0;
        const LightDirectionSample sample = sample_light_direction(light, point, u);
        const LightDirectionSample expected = expected_light_direction(light, point, u);
        CHECK(within_path_tolerance(sample.pdf, expected.pdf));
        CHECK(within_path_tolerance(sample.distance, expected.distance));
        CHECK(within_path_tolerance(light_direction_pdf(light, point, sample.direction),
                                    expected.pdf));
    }
}
