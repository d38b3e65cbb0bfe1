// Public tests for stage 8, area lights and soft shadows. Run them with
// `ctest --preset student -L stage8`, one function's with
// `build/student/bin/raystep_stage8_tests "sample_quad_light:*"`.
//
// sample_quad_light is held against numbers worked by hand: a light straight overhead, its back,
// a tilted one. quad_light_shading is tested without a scene: the OccludedFunction is a lambda
// that answers "nothing blocks" or "everything blocks" and records the shadow rays it is asked
// about. Each test calls your function before its CHECKs, so a stub is reported once. A loop over
// cases stops at the first that fails, and a function built from others names them: fix theirs
// first.

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "base/testing/catch.h"
#include "base/testing/number_text.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/8_sampling/sampling.h"

using namespace raystep;
using raystep::testing::exact_text;
using raystep::testing::IsNear;
using raystep::testing::uses;

namespace {

const double kPi = 3.14159265358979323846;

// A light of area 0.25 (0.5 x 0.5) in the plane y = 2, centred over the origin, shining down:
// ab x ac = (0, 0, 0.5) x (0.5, 0, 0) = (0, 0.25, 0) points up, away from the emitting side
// ac x ab, which faces down. u = (0.5, 0.5) is its centre, (0, 2, 0).
const QuadLight kOverhead{{-0.25, 2, -0.25}, {0, 0, 0.5}, {0.5, 0, 0}, {1, 2, 4}};

// Each channel of got within a relative `tolerance` of expected; the first channel that is not
// ends the test case.
void check_colour(const Color& got, const Color& expected, double tolerance) {
    INFO("got " << exact_text(got) << ", expected " << exact_text(expected) << ", each within "
                << raystep::testing::size_text(tolerance) << " x |expected|");
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        REQUIRE(got[c] == Approx(expected[c]).epsilon(tolerance).margin(0.0));
    }
}

// A floor point at the origin, seen from straight above: normal and V up, no rounding error.
SurfacePoint floor_point() {
    return {{0, 0, 0}, Vec3(0.0), {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
}

// A matte material: Kd only, so one light's term is intensity Kd (N . L).
Material matte(const Color& diffuse) {
    Material material;
    material.diffuse = diffuse;
    return material;
}

const RayOffset kAlongRay{OffsetRule::along_ray, 0.125};

}  // namespace

TEST_CASE("sample_quad_light: straight overhead, radiance A / (pi d^2), cos(theta_l) = 1",
          "[stage8]") {
    INFO(uses("sample_quad_light", "stage 1's cross, dot and length"));
    INFO(
        "From the origin to the light's centre (0, 2, 0): L = (0, 1, 0), d = 2, the light faces "
        "the point head-on. Area 0.25, one sample: intensity = (1, 2, 4) 0.25 / (pi 4) = "
        "(1, 2, 4) / (16 pi).");
    const LightSample sample = sample_quad_light(kOverhead, {0, 0, 0}, {0.5, 0.5}, 1);
    CHECK_THAT(sample.direction, IsNear(Vec3{0, 1, 0}, 1e-15));
    CHECK(sample.distance == Approx(2.0).epsilon(1e-15));
    check_colour(sample.intensity, Color(1, 2, 4) / (16 * kPi), 1e-14);
}

TEST_CASE("sample_quad_light: the intensity is shared among sample_count samples", "[stage8]") {
    INFO(uses("sample_quad_light", "stage 1's cross, dot and length"));
    INFO("The same sample as one of 4: a quarter of it, (1, 2, 4) / (64 pi).");
    const LightSample sample = sample_quad_light(kOverhead, {0, 0, 0}, {0.5, 0.5}, 4);
    check_colour(sample.intensity, Color(1, 2, 4) / (64 * kPi), 1e-14);
}

TEST_CASE("sample_quad_light: u picks the point a + u.x ab + u.y ac of the light", "[stage8]") {
    INFO(uses("sample_quad_light", "stage 1's cross, dot and length"));
    INFO(
        "u = (0, 0) is the corner a = (-0.25, 2, -0.25): d^2 = 4.125, and the light leans away by "
        "cos(theta_l) = 2 / d. u = (0.5, 0) is a + ab / 2 = (-0.25, 2, 0): d^2 = 4.0625.");
    for (const auto& [u, y] : {std::pair{Vec2{0, 0}, Vec3{-0.25, 2, -0.25}},
                               std::pair{Vec2{0.5, 0}, Vec3{-0.25, 2, 0}}}) {
        CAPTURE(u.x, u.y);
        const LightSample sample = sample_quad_light(kOverhead, {0, 0, 0}, u, 1);
        const double d = std::sqrt(y.x * y.x + y.y * y.y + y.z * y.z);
        REQUIRE_THAT(sample.direction, IsNear(y / d, 1e-15));
        REQUIRE(sample.distance == Approx(d).epsilon(1e-15));
        check_colour(sample.intensity, Color(1, 2, 4) * 0.25 * (2 / d) / (kPi * d * d), 1e-14);
    }
}

TEST_CASE("sample_quad_light: from behind the light, the intensity is 0", "[stage8]") {
    INFO(uses("sample_quad_light", "stage 1's cross, dot and length"));
    INFO(
        "The point (0, 4, 0) is above the light, which shines down only: cos(theta_l) < 0 counts "
        "as 0. L and d are still the way to the light: (0, -1, 0), 2.");
    const LightSample sample = sample_quad_light(kOverhead, {0, 4, 0}, {0.5, 0.5}, 1);
    CHECK(sample.intensity == Color(0.0));
    CHECK_THAT(sample.direction, IsNear(Vec3{0, -1, 0}, 1e-15));
    CHECK(sample.distance == Approx(2.0).epsilon(1e-15));
}

TEST_CASE("sample_quad_light: a light tilted by 60 degrees gives half, cos(theta_l) = 1/2",
          "[stage8]") {
    INFO(uses("sample_quad_light", "stage 1's cross, dot and length"));
    INFO(
        "The overhead light turned 60 degrees about the z axis through its centre: ac = 0.5 (cos "
        "60, sin 60, 0), so ab x ac = 0.25 (-sin 60, cos 60, 0) and (ab x ac) . L / A = cos 60 = "
        "1/2 for L = (0, 1, 0). Same area, same distance: half the overhead intensity, (1, 2, 4) "
        "/ (32 pi).");
    const Vec3 ab{0, 0, 0.5};
    const Vec3 ac = 0.5 * Vec3{0.5, std::sqrt(3.0) / 2, 0};
    const QuadLight tilted{Vec3{0, 2, 0} - 0.5 * ab - 0.5 * ac, ab, ac, {1, 2, 4}};
    const LightSample sample = sample_quad_light(tilted, {0, 0, 0}, {0.5, 0.5}, 1);
    CHECK_THAT(sample.direction, IsNear(Vec3{0, 1, 0}, 1e-15));
    check_colour(sample.intensity, Color(1, 2, 4) / (32 * kPi), 1e-14);
}

TEST_CASE("sample_quad_light: a point on the light throws std::domain_error", "[stage8]") {
    INFO(uses("sample_quad_light", "stage 1's cross, dot and length"));
    INFO("From the light's own centre there is no direction to it.");
    const LightSample ahead = sample_quad_light(kOverhead, {0, 1, 0}, {0.5, 0.5}, 1);
    CHECK(ahead.distance == Approx(1.0));
    CHECK_THROWS_AS(sample_quad_light(kOverhead, {0, 2, 0}, {0.5, 0.5}, 1), std::domain_error);
}

TEST_CASE("quad_light_shading: a tiny light unblocked: N samples add up to one light's term",
          "[stage8]") {
    INFO(uses("quad_light_shading", "sample_quad_light, samples, stage 6"));
    INFO(
        "A 1e-3 x 1e-3 light 2 above a matte floor point (Kd = (0.5, 0.25, 1)), shining down: "
        "every sample sees it head-on from about 2 away, so each adds Kd (1, 2, 4) A / (pi 4 N) "
        "and the 16 together Kd (1, 2, 4) 1e-6 / (4 pi), to within 1e-6 (the light's width moves "
        "the cosines and distances by less). Dividing by N twice, or not at all, is off by 16.");
    const double s = 1e-3;
    const QuadLight tiny{{-s / 2, 2, -s / 2}, {0, 0, s}, {s, 0, 0}, {1, 2, 4}};
    const Color kd{0.5, 0.25, 1};
    int calls = 0;
    const OccludedFunction nothing = [&calls](const Ray&) {
        ++calls;
        return false;
    };
    RandomStream random(11, 0);
    const Color got = quad_light_shading(matte(kd), floor_point(), tiny, SamplePattern::jittered,
                                         16, random, nothing, kAlongRay);
    check_colour(got, kd * Color(1, 2, 4) * (s * s / (4 * kPi)), 1e-6);
    CHECK(calls == 16);
}

TEST_CASE("quad_light_shading: a light blocked everywhere adds black", "[stage8]") {
    INFO(uses("quad_light_shading", "sample_quad_light, samples, stage 6"));
    INFO("Every shadow ray is blocked: no sample adds anything, and each one asked.");
    int calls = 0;
    const OccludedFunction everything = [&calls](const Ray&) {
        ++calls;
        return true;
    };
    RandomStream random(11, 1);
    const Color got = quad_light_shading(matte(Color(1.0)), floor_point(), kOverhead,
                                         SamplePattern::jittered, 9, random, everything, kAlongRay);
    CHECK(got == Color(0.0));
    CHECK(calls == 9);
}

TEST_CASE("quad_light_shading: samples behind the surface trace no shadow ray", "[stage8]") {
    INFO(uses("quad_light_shading", "sample_quad_light, samples, stage 6"));
    INFO(
        "A light below the floor (y = -2, shining up): N . L < 0 for every sample, so nothing is "
        "added and no shadow ray is asked for.");
    const QuadLight below{{-0.25, -2, -0.25}, {0.5, 0, 0}, {0, 0, 0.5}, {1, 1, 1}};
    int calls = 0;
    const OccludedFunction nothing = [&calls](const Ray&) {
        ++calls;
        return false;
    };
    RandomStream random(11, 2);
    const Color got = quad_light_shading(matte(Color(1.0)), floor_point(), below,
                                         SamplePattern::jittered, 16, random, nothing, kAlongRay);
    CHECK(got == Color(0.0));
    CHECK(calls == 0);
}

TEST_CASE("quad_light_shading: a light across the horizon: shadow rays only above it", "[stage8]") {
    INFO(uses("quad_light_shading", "sample_quad_light, samples, stage 6"));
    INFO(
        "A 2 x 2 light in the plane x = 2, facing the floor point at the origin, from y = -1 to "
        "y = 1: with 4 x 4 jittered samples the 2 upper rows of strata are above the floor and "
        "the 2 lower rows below it. 8 shadow rays, each from the point itself (along_ray, "
        "epsilon 0.125) towards its sample, ending at the light.");
    const QuadLight upright{{2, -1, -1}, {0, 2, 0}, {0, 0, 2}, {1, 1, 1}};
    std::vector<Ray> asked;
    const OccludedFunction nothing = [&asked](const Ray& ray) {
        asked.push_back(ray);
        return false;
    };
    RandomStream random(11, 3);
    quad_light_shading(matte(Color(1.0)), floor_point(), upright, SamplePattern::jittered, 16,
                       random, nothing, kAlongRay);
    REQUIRE(asked.size() == 8);
    for (const Ray& ray : asked) {
        INFO("shadow ray: origin " << exact_text(ray.origin) << ", direction "
                                   << exact_text(ray.direction) << ", t in [" << ray.t_min << ", "
                                   << ray.t_max << "]");
        REQUIRE(ray.origin == Vec3(0, 0, 0));
        REQUIRE(ray.direction.y > 0.0);
        REQUIRE(ray.t_min == 0.125);
        // It ends on the plane x = 2: t_max D.x = 2.
        REQUIRE(ray.t_max * ray.direction.x == Approx(2.0).epsilon(1e-14));
    }
}
