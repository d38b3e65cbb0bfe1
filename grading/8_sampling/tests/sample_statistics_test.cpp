// The statistics of the grader's random checks (grading/8_sampling/sample_statistics.h) against
// published values, and against their own false-fail rates on uniform points drawn by
// PortableRandom; and stage 8's expectations (grading/8_sampling/sampling_oracle.h) against closed
// forms. The chi-square p-value they use has its tests in base/math/tests/chi_square_test.cpp.

#include <cmath>
#include <limits>
#include <vector>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "base/testing/special_values.h"
#include "grading/8_sampling/sample_statistics.h"
#include "grading/8_sampling/sampling_oracle.h"

using namespace raystep;
using namespace raystep::grade;

namespace {

using raystep::testing::kNaN;
constexpr double kPi = 3.14159265358979323846;

}  // namespace

TEST_CASE("normal bounds: the tables' 1.96 and 1.645, and far tails", "[grader]") {
    CHECK(two_sided_normal_bound(0.05) == Approx(1.959963984540054).epsilon(1e-12));
    CHECK(one_sided_normal_bound(0.05) == Approx(1.6448536269514722).epsilon(1e-12));
    // scipy.stats.norm.isf(1e-4 / 24)
    CHECK(two_sided_normal_bound(1e-4 / 12) == Approx(4.4566).epsilon(1e-4));
}

TEST_CASE("uniform_square_chi_square: an even histogram is 0, a point outside or NaN infinite",
          "[grader]") {
    std::vector<Vec2> even;
    for (int b = 0; b < 10; ++b) {
        for (int a = 0; a < 10; ++a)
            even.push_back({(a + 0.5) / 10, (b + 0.5) / 10});
    }
    CHECK(uniform_square_chi_square(even, 10) == 0.0);
    // All in one bin of four: counts (4, 0, 0, 0) against 1 each, (9 + 1 + 1 + 1) / 1.
    CHECK(uniform_square_chi_square({{0.1, 0.1}, {0.2, 0.2}, {0.3, 0.3}, {0.4, 0.4}}, 2) == 12.0);
    std::vector<Vec2> outside = even;
    outside.push_back({1.0, 0.5});
    CHECK(std::isinf(uniform_square_chi_square(outside, 10)));
    outside.back() = {kNaN, 0.5};
    CHECK(std::isinf(uniform_square_chi_square(outside, 10)));
}

TEST_CASE("chi-square of uniform points fails at its stated rate, and a half-square bias always",
          "[grader]") {
    // 400 trials of 8000 points at alpha = 0.05: 20 failures expected, standard deviation 4.4;
    // outside [5, 40] has probability below 1e-5.
    int failures = 0;
    int biased_failures = 0;
    for (std::uint64_t trial = 0; trial < 400; ++trial) {
        PortableRandom random(2024, trial);
        std::vector<Vec2> points;
        std::vector<Vec2> biased;
        for (int k = 0; k < 8000; ++k) {
            const Vec2 p{random.unit(), random.unit()};
            points.push_back(p);
            // Offsets in a jittered stratum's lower 90%: the weakest bias a mutant could have.
            biased.push_back({0.9 * p.x, p.y});
        }
        failures += chi_square_p_value(uniform_square_chi_square(points, 10), 99) < 0.05;
        biased_failures += chi_square_p_value(uniform_square_chi_square(biased, 10), 99) < 1e-4;
    }
    CHECK(failures >= 5);
    CHECK(failures <= 40);
    CHECK(biased_failures == 400);
}

TEST_CASE("estimate_mean: the mean, the spread and its floor", "[grader]") {
    const MeanEstimate e = estimate_mean({1, 2, 3, 4}, 0.0);
    CHECK(e.mean == 2.5);
    CHECK(e.deviation == Approx(std::sqrt(5.0 / 3.0)));
    CHECK(e.standard_error == Approx(std::sqrt(5.0 / 3.0) / 2));
    // No spread: the floor stands in, so a bias of 1e-6 is 2000 standard errors.
    const MeanEstimate flat = estimate_mean({0.5, 0.5, 0.5, 0.5}, 1e-9);
    CHECK(flat.deviation == 0.0);
    CHECK(flat.standard_error == Approx(5e-10));
    CHECK_FALSE(mean_consistent(flat, 0.5 + 1e-6, 5.0));
    CHECK(mean_consistent(flat, 0.5, 5.0));
    CHECK_FALSE(mean_consistent({kNaN, 1.0, 1.0}, 0.0, 5.0));
}

TEST_CASE("variance_not_above: stratified-like spread passes, random-like spread fails",
          "[grader]") {
    std::vector<double> narrow;
    std::vector<double> wide;
    for (std::uint64_t k = 0; k < 400; ++k) {
        PortableRandom random(7, k);
        const double u = random.unit() - 0.5;
        narrow.push_back(0.01 * u);  // variance 1e-4 / 12
        wide.push_back(0.05 * u);    // 25 times as much
    }
    const double bound = one_sided_normal_bound(1e-5);
    CHECK(variance_not_above(narrow, 1e-4 / 12, bound));
    CHECK_FALSE(variance_not_above(wide, 1e-4 / 12, bound));
    CHECK_FALSE(variance_not_above({kNaN, 1.0, 2.0}, 1.0, bound));
}

TEST_CASE("half_plane_share: a vertical edge, the diagonal, and an edge that misses", "[grader]") {
    CHECK(half_plane_share({3, 5}, {4, 6}, {3.25, 0}, {1, 0}) == Approx(0.75));
    CHECK(half_plane_share({3, 5}, {4, 6}, {3.5, 5.5}, {1, 1}) == Approx(0.5));
    // A corner triangle: the line x + y = 3.5 + 5 cuts the triangle of legs 0.5 off (3, 5).
    CHECK(half_plane_share({3, 5}, {4, 6}, {3.5, 5}, {-1, -1}) == Approx(0.125));
    CHECK(half_plane_share({3, 5}, {4, 6}, {10, 10}, {1, 0}) == 0.0);
    CHECK(half_plane_share({3, 5}, {4, 6}, {0, 0}, {1, 0}) == Approx(1.0));
}

// The form factor from a point to a parallel a x b rectangle above it at height c, the point under
// one corner (Howell, A Catalog of Radiation Heat Transfer Configuration Factors, B-3).
double corner_form_factor(double a, double b, double c) {
    const double x = a / c;
    const double y = b / c;
    return (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
            y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
           (2 * kPi);
}

TEST_CASE("quad_light_integral: a diffuse point under a light's corner is L times the form factor",
          "[grader]") {
    const double a = 2.0, b = 1.0, c = 1.5;
    // ab along z (length b), ac along x (length a): emitting towards ac x ab, downwards.
    const QuadLight light{{0, c, 0}, {0, 0, b}, {a, 0, 0}, {2, 1, 0.5}, 0};
    Material diffuse;
    diffuse.diffuse = Color(1.0);
    const SurfacePoint point{{0, 0, 0}, Vec3(0.0), {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    const double whole = corner_form_factor(a, b, c);
    const Color got = quad_light_integral(diffuse, point, light, 0.0, 64);
    // The midpoint rule alone on 64 x 64 cells is some 1e-4 off; extrapolated, 1e-8 at most.
    CHECK(got.x == Approx(2 * whole).epsilon(1e-8));
    CHECK(got.y == Approx(whole).epsilon(1e-8));
    CHECK(got.z == Approx(0.5 * whole).epsilon(1e-8));
    // u.x < 0.5 blocked: the half of ab next to the corner, so the rest is the whole rectangle's
    // form factor less that of the a x b/2 one over the same corner.
    const Color seen = quad_light_integral(diffuse, point, light, 0.5, 64);
    CHECK(seen.y == Approx(whole - corner_form_factor(a, 0.5 * b, c)).epsilon(1e-8));
}

TEST_CASE("regular_quad_light_sum: the mean of the integrand at the stratum centres", "[grader]") {
    const QuadLight light{{-1, 2, -1}, {0, 0, 2}, {2, 0, 0}, {1, 1, 1}, 0};
    Material diffuse;
    diffuse.diffuse = Color(0.5);
    const SurfacePoint point{{0, 0, 0}, Vec3(0.0), {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    // One stratum: the light's middle, straight above at distance 2, seen face-on:
    // 0.5 x A cos cos / (pi d^2) = 0.5 x 4 / (4 pi).
    CHECK(regular_quad_light_sum(diffuse, point, light, 1, 0.0).x == Approx(0.5 / kPi));
    // Blocked where the only centre is: nothing.
    CHECK(regular_quad_light_sum(diffuse, point, light, 1, 0.75).x == 0.0);
}
