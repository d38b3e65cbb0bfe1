// Public tests for stage 10, directions over the hemisphere and their densities. Run them with
// `ctest --preset student -L stage10`, one function's with
// `build/student/bin/raystep_stage10_tests "cosine_hemisphere:*"`.
//
// A sampler is tested as Nori's warp test does: 200,000 directions binned over the sphere and
// compared with the count its density predicts in each bin, by a chi-square test that a right
// sampler fails with probability 1e-6 (direction_test.h). The density the samples are held
// against is the contract's formula, written out here; the _pdf functions are tested against
// the same formula, and must integrate to 1 over the sphere.

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
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

// The contract's densities, in the lobe's frame.
double uniform_density(const Vec3& d) {
    return d.z >= 0.0 ? 1.0 / (2.0 * kPi) : 0.0;
}
double cosine_density(const Vec3& d) {
    return std::max(d.z, 0.0) / kPi;
}
double phong_density(const Vec3& d, double s) {
    return d.z >= 0.0 ? (s + 1.0) / (2.0 * kPi) * std::pow(d.z, s) : 0.0;
}
double ggx_d(const Vec3& h, double alpha) {
    if (h.z <= 0.0) return 0.0;
    const double cos2 = h.z * h.z;
    const double tan2 = (1.0 - cos2) / cos2;
    const double a2 = alpha * alpha;
    return a2 / (kPi * cos2 * cos2 * (a2 + tan2) * (a2 + tan2));
}

const Vec3 kDirections[] = {
    {0.0, 0.0, 1.0}, {0.6, 0.0, 0.8},    {-0.36, 0.48, 0.8}, {0.0, 0.6, -0.8},
    {1.0, 0.0, 0.0}, {0.28, -0.96, 0.0}, {0.0, 0.0, -1.0},   {0.48, 0.64, 0.6},
};

}  // namespace

TEST_CASE("frame_around: w is n, and u, v, w are orthonormal and right-handed", "[stage10]") {
    INFO(uses("frame_around", "stage 1's orthonormal_frame"));
    const Vec3 normals[] = {{0, 0, 1},
                            {0, 0, -1},
                            {1, 0, 0},
                            {0, 1, 0},
                            {0.6, 0, 0.8},
                            {0.48, 0.64, 0.6},
                            {1e-12, 0, 1},
                            {0, -1, 1e-9},
                            {0.57735026918962573, 0.57735026918962573, 0.57735026918962573}};
    for (const Vec3& raw : normals) {
        const Vec3 n = glm::normalize(raw);
        CAPTURE(n);
        const Frame frame = frame_around(n);
        CHECK_THAT(frame.w, IsNear(n, 1e-15));
        CHECK(std::abs(glm::dot(frame.u, frame.v)) < 1e-15);
        CHECK(std::abs(glm::dot(frame.u, frame.w)) < 1e-15);
        CHECK(std::abs(glm::length(frame.u) - 1.0) < 1e-15);
        CHECK(std::abs(glm::length(frame.v) - 1.0) < 1e-15);
        CHECK_THAT(glm::cross(frame.u, frame.v), IsNear(frame.w, 1e-15));
    }
}

TEST_CASE("to_world: the local axes go to u, v and w, and to_local takes them back", "[stage10]") {
    const Frame frame{{0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}, {1.0, 0.0, 0.0}};
    CHECK(to_world(frame, {1.0, 2.0, 3.0}) == Vec3(3.0, 1.0, 2.0));
    const Frame tilted = frame_around(glm::normalize(Vec3(1.0, 2.0, 3.0)));
    for (const Vec3& d : kDirections) {
        CAPTURE(d);
        CHECK_THAT(to_local(tilted, to_world(tilted, d)), IsNear(d, 1e-15));
    }
}

TEST_CASE("to_local: (d . u, d . v, d . w)", "[stage10]") {
    const Frame frame{{0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}, {1.0, 0.0, 0.0}};
    CHECK(to_local(frame, {3.0, 1.0, 2.0}) == Vec3(1.0, 2.0, 3.0));
}

TEST_CASE("uniform_hemisphere: u.x is cos(theta), u.y a turn of phi", "[stage10]") {
    CHECK_THAT(uniform_hemisphere({1.0, 0.0}), IsNear(Vec3(0.0, 0.0, 1.0), 1e-15));
    CHECK_THAT(uniform_hemisphere({0.0, 0.25}), IsNear(Vec3(0.0, 1.0, 0.0), 1e-15));
    CHECK_THAT(uniform_hemisphere({0.8, 0.5}), IsNear(Vec3(-0.6, 0.0, 0.8), 1e-15));
}

TEST_CASE("uniform_hemisphere: its directions pass the chi-square test against 1 / (2 pi)",
          "[stage10]") {
    const auto result = direction_chi_square(uniform_hemisphere, uniform_density, 10);
    INFO(result.problem);
    REQUIRE(result.problem.empty());
    CHECK(result.p_value > kSignificance);
}

TEST_CASE("uniform_hemisphere_pdf: 1 / (2 pi) above, 0 below, integrating to 1", "[stage10]") {
    for (const Vec3& d : kDirections) {
        CAPTURE(d);
        CHECK_THAT(uniform_hemisphere_pdf(d), IsNear(uniform_density(d), 1e-15));
    }
    CHECK_THAT(sphere_integral(uniform_hemisphere_pdf), IsNear(1.0, 1e-9));
}

TEST_CASE("cosine_hemisphere: the disk's point lifted, u.x the squared radius", "[stage10]") {
    CHECK_THAT(cosine_hemisphere({0.0, 0.3}), IsNear(Vec3(0.0, 0.0, 1.0), 1e-15));
    CHECK_THAT(cosine_hemisphere({0.36, 0.0}), IsNear(Vec3(0.6, 0.0, 0.8), 1e-15));
}

TEST_CASE("cosine_hemisphere: its directions pass the chi-square test against cos / pi",
          "[stage10]") {
    const auto result = direction_chi_square(cosine_hemisphere, cosine_density, 11);
    INFO(result.problem);
    REQUIRE(result.problem.empty());
    CHECK(result.p_value > kSignificance);
}

TEST_CASE("cosine_hemisphere: a uniform sampler fails its chi-square test", "[stage10]") {
    // The test's power: uniform directions held against cos / pi.
    const auto result = direction_chi_square(uniform_hemisphere, cosine_density, 11);
    CHECK(result.p_value < kSignificance);
}

TEST_CASE("cosine_hemisphere_pdf: cos / pi above, 0 below, integrating to 1", "[stage10]") {
    for (const Vec3& d : kDirections) {
        CAPTURE(d);
        CHECK_THAT(cosine_hemisphere_pdf(d), IsNear(cosine_density(d), 1e-15));
    }
    CHECK_THAT(sphere_integral(cosine_hemisphere_pdf), IsNear(1.0, 1e-6));
}

TEST_CASE("phong_lobe: its directions pass the chi-square test for exponents 1 to 30",
          "[stage10]") {
    for (double s : {1.0, 5.0, 30.0}) {
        CAPTURE(s);
        const auto result =
            direction_chi_square([s](const Vec2& u) { return phong_lobe(u, s); },
                                 [s](const Vec3& d) { return phong_density(d, s); }, 12);
        INFO(result.problem);
        REQUIRE(result.problem.empty());
        CHECK(result.p_value > kSignificance);
    }
}

TEST_CASE("phong_lobe_pdf: (s + 1) / (2 pi) cos^s, integrating to 1", "[stage10]") {
    for (double s : {0.0, 1.0, 5.0, 30.0}) {
        for (const Vec3& d : kDirections) {
            CAPTURE(s, d);
            CHECK_THAT(phong_lobe_pdf(d, s), IsNear(phong_density(d, s), 1e-14));
        }
        // A density of z alone: many rows, few columns.
        const auto pdf = [s](const Vec3& d) { return phong_lobe_pdf(d, s); };
        CHECK_THAT(sphere_integral(pdf, 100000, 4), IsNear(1.0, 1e-6));
    }
}

TEST_CASE("ggx_distribution: 1 / (pi alpha^2) along the normal, 0 below, D cos integrating to 1",
          "[stage10]") {
    for (double alpha : {0.1, 0.3, 0.8}) {
        CAPTURE(alpha);
        CHECK_THAT(ggx_distribution({0.0, 0.0, 1.0}, alpha),
                   IsNear(1.0 / (kPi * alpha * alpha), 1e-12));
        for (const Vec3& d : kDirections) {
            CAPTURE(d);
            CHECK_THAT(ggx_distribution(d, alpha),
                       IsNear(ggx_d(d, alpha), 1e-12 * (1.0 + ggx_d(d, alpha))));
        }
    }
    // Near the horizon cos^4 underflows in the formula as written; D must stay finite, and 0 on
    // it.
    CHECK(std::isfinite(ggx_distribution({1.0, 0.0, 1e-200}, 0.3)));
    CHECK(ggx_distribution({1.0, 0.0, 0.0}, 0.3) == 0.0);
    // Along the normal at alpha = 1e-9, alpha^2 - 1 rounds to -1 and 1 - cos^2 to 0: D must still
    // be 1 / (pi alpha^2), not infinite.
    CHECK_THAT(ggx_distribution({0.0, 0.0, 1.0}, 1e-9), IsNear(1.0 / (kPi * 1e-18), 1e-12));
}

TEST_CASE("ggx_half_vector: its half vectors pass the chi-square test against D cos", "[stage10]") {
    for (double alpha : {0.2, 0.5, 1.0}) {
        CAPTURE(alpha);
        const auto result = direction_chi_square(
            [alpha](const Vec2& u) { return ggx_half_vector(u, alpha); },
            [alpha](const Vec3& h) { return ggx_d(h, alpha) * std::max(h.z, 0.0); }, 13);
        INFO(result.problem);
        REQUIRE(result.problem.empty());
        CHECK(result.p_value > kSignificance);
    }
}

TEST_CASE("ggx_half_vector_pdf: D(h) cos(theta_h), integrating to 1", "[stage10]") {
    for (double alpha : {0.2, 0.5, 1.0}) {
        CAPTURE(alpha);
        for (const Vec3& d : kDirections) {
            CAPTURE(d);
            const double expected = ggx_d(d, alpha) * std::max(d.z, 0.0);
            CHECK_THAT(ggx_half_vector_pdf(d, alpha), IsNear(expected, 1e-12 * (1.0 + expected)));
        }
        const auto pdf = [alpha](const Vec3& h) { return ggx_half_vector_pdf(h, alpha); };
        CHECK_THAT(sphere_integral(pdf, 100000, 4), IsNear(1.0, 1e-6));
    }
}
