// Public tests for stage 10, sampling a quad light by solid angle. The light is the square of
// side 2 one unit above the origin, facing down; seen from the origin, its form factor has a
// closed form (a point under the corner of a parallel rectangle, four times over).

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/vec3_matchers.h"
#include "stages/10_path_tracing/path_tracing.h"

using namespace raystep;
using raystep::testing::IsNear;

namespace {

constexpr double kPi = glm::pi<double>();

// a = (-1, -1, 1), ab along x, ac along y: ac x ab = (0, 0, -4) faces down; area 4.
const QuadLight kLight{{-1.0, -1.0, 1.0}, {2.0, 0.0, 0.0}, {0.0, 2.0, 0.0}, {2.0, 1.0, 0.5}, 1};

// The form factor from a point to a parallel rectangle of sides a x b at height h, the point
// under one corner: (1 / 2 pi) (A / sqrt(1 + A^2) atan(B / sqrt(1 + A^2)) + the same with A and B
// swapped), A = a / h, B = b / h.
double corner_form_factor(double a, double b, double h) {
    const double x = a / h;
    const double y = b / h;
    return (x / std::sqrt(1.0 + x * x) * std::atan(y / std::sqrt(1.0 + x * x)) +
            y / std::sqrt(1.0 + y * y) * std::atan(x / std::sqrt(1.0 + y * y))) /
           (2.0 * kPi);
}

}  // namespace

TEST_CASE("sample_light_direction: the point of u, its distance, d^2 / (A cos) and the radiance",
          "[stage10]") {
    const LightDirectionSample centre = sample_light_direction(kLight, Vec3(0.0), {0.5, 0.5});
    CHECK_THAT(centre.direction, IsNear(Vec3(0.0, 0.0, 1.0), 1e-15));
    CHECK_THAT(centre.distance, IsNear(1.0, 1e-15));
    CHECK_THAT(centre.pdf, IsNear(0.25, 1e-15));
    CHECK(centre.radiance == kLight.radiance);
    // The corner (1, 1, 1) from the origin: d^2 = 3, cos = 1 / sqrt(3).
    const LightDirectionSample corner = sample_light_direction(kLight, Vec3(0.0), {1.0, 1.0});
    CHECK_THAT(corner.direction, IsNear(Vec3(1.0) / std::sqrt(3.0), 1e-15));
    CHECK_THAT(corner.pdf, IsNear(3.0 / (4.0 / std::sqrt(3.0)), 1e-14));
}

TEST_CASE("sample_light_direction: black from behind, density 0 on the light's plane",
          "[stage10]") {
    const LightDirectionSample behind = sample_light_direction(kLight, {0.0, 0.0, 2.0}, {0.5, 0.5});
    CHECK(behind.radiance == Color(0.0));
    CHECK_THAT(behind.pdf, IsNear(0.25, 1e-15));
    const LightDirectionSample edge_on =
        sample_light_direction(kLight, {5.0, 0.0, 1.0}, {0.5, 0.5});
    CHECK(edge_on.pdf == 0.0);
    CHECK(edge_on.radiance == Color(0.0));
}

TEST_CASE("light_direction_pdf: the sample's density where the ray meets the light, else 0",
          "[stage10]") {
    const Vec3 point{0.3, -0.2, 0.1};
    RandomStream random(30, 0);
    for (int k = 0; k < 100; ++k) {
        const LightDirectionSample sample = sample_light_direction(kLight, point, random.next2());
        CAPTURE(k, sample.direction);
        CHECK_THAT(light_direction_pdf(kLight, point, sample.direction), IsNear(sample.pdf, 1e-12));
    }
    CHECK(light_direction_pdf(kLight, point, {0.0, 0.0, -1.0}) == 0.0);
    CHECK(light_direction_pdf(kLight, point, glm::normalize(Vec3(5.0, 0.0, 1.0))) == 0.0);
    CHECK(light_direction_pdf(kLight, point, {1.0, 0.0, 0.0}) == 0.0);
}

TEST_CASE("sample_light_direction: the mean of L cos / p is the irradiance, pi L F", "[stage10]") {
    // Under the centre of the square: four corners' form factors.
    const double form_factor = 4.0 * corner_form_factor(1.0, 1.0, 1.0);
    RandomStream random(31, 0);
    constexpr int kCount = 100000;
    double sum = 0.0;
    double sum2 = 0.0;
    for (int k = 0; k < kCount; ++k) {
        const LightDirectionSample sample =
            sample_light_direction(kLight, Vec3(0.0), random.next2());
        const double value = sample.radiance.x * sample.direction.z / sample.pdf;
        sum += value;
        sum2 += value * value;
    }
    const double mean = sum / kCount;
    const double error = std::sqrt((sum2 / kCount - mean * mean) / kCount);
    INFO("mean " << mean << ", standard error " << error);
    // Five standard errors: a right sampler is further off with probability 6e-7.
    CHECK(std::abs(mean - 2.0 * kPi * form_factor) < 5.0 * error);
}
