#include "renderer/spot_light.h"

#include <cmath>

#include "base/testing/catch.h"

using namespace raystep;

namespace {

// At the origin, shining down -y, 30 degrees wide, falling off as cos^2.
SpotLight down_spot() {
    SpotLight spot;
    spot.position = Vec3(0.0);
    spot.direction = Vec3(0, -2, 0);  // not unit: only its direction counts
    spot.cutoff_degrees = 30.0;
    spot.exponent = 2.0;
    spot.color = Color(1.0, 0.5, 0.25);
    return spot;
}

}  // namespace

TEST_CASE("spot_falloff: 1 on the axis, cos^exponent inside the cone, 0 beyond the cutoff",
          "[app]") {
    const SpotLight spot = down_spot();
    CHECK(spot_falloff(spot, Vec3(0, -3, 0)) == Approx(1.0));
    // 20 degrees off the axis: cos(20)^2
    const double angle = 20.0 * 3.14159265358979 / 180.0;
    CHECK(spot_falloff(spot, Vec3(std::sin(angle), -std::cos(angle), 0)) ==
          Approx(std::pow(std::cos(angle), 2.0)));
    // 40 degrees off, and behind the light
    CHECK(spot_falloff(spot, Vec3(std::sin(0.7), -std::cos(0.7), 0)) == 0.0);
    CHECK(spot_falloff(spot, Vec3(0, 1, 0)) == 0.0);
    CHECK(spot_falloff(spot, spot.position) == 0.0);
}

TEST_CASE("sample_spot_light: a point light's sample with the colour scaled by the falloff",
          "[app]") {
    SpotLight spot = down_spot();
    spot.attenuation = {1.0, 0.0, 1.0};
    const LightSample sample = sample_spot_light(spot, Vec3(0, -2, 0));
    CHECK(sample.direction == Vec3(0, 1, 0));
    CHECK(sample.distance == Approx(2.0));
    // colour / (1 + d^2) on the axis
    CHECK(sample.intensity.r == Approx(0.2));
    CHECK(sample.intensity.g == Approx(0.1));
    CHECK(sample_spot_light(spot, Vec3(3, -1, 0)).intensity == Color(0.0));
}
