// Public tests for stage 9, Snell's law and the Fresnel reflectance. Run them with
// `ctest --preset student -L stage9`, one function's with
// `build/student/bin/raystep_stage9_tests "refract:*"`.
//
// Every case is worked by hand in its message: the angles are chosen so that sines and cosines
// are simple (45, 60 degrees, Brewster's angle of glass), and the tolerances are a few units of
// rounding of a double (1.1e-16 each). Each test calls your function before its CHECKs: a stub
// is reported once. A loop over angles stops at the first that fails.

#include <cmath>
#include <optional>

#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/9_refraction/refraction.h"

using namespace raystep;
using raystep::testing::IsNear;
using raystep::testing::uses;

namespace {

const double kPi = 3.14159265358979323846;

double radians(double degrees) {
    return degrees * kPi / 180;
}

// The unit direction of a ray going down onto the floor y = 0 at angle theta from its normal
// (0, 1, 0), travelling towards +x.
Vec3 falling_at(double theta) {
    return {std::sin(theta), -std::cos(theta), 0};
}

const Vec3 kUp{0, 1, 0};

}  // namespace

TEST_CASE("refract: head-on, the ray goes straight through", "[stage9]") {
    INFO(uses("refract", "stage 1's dot"));
    INFO("D = (0, -1, 0) into glass, eta = 1 / 1.5: no tangential part to scale, T = D.");
    const std::optional<Vec3> t = refract({0, -1, 0}, kUp, 1 / 1.5);
    REQUIRE(t);
    CHECK_THAT(*t, IsNear(Vec3{0, -1, 0}, 1e-15));
}

TEST_CASE("refract: 45 degrees into glass obeys Snell's law, unit length, on the far side",
          "[stage9]") {
    INFO(uses("refract", "stage 1's dot"));
    INFO(
        "From air (n1 = 1) at 45 degrees into glass (n2 = 1.5): sin(theta2) = sin 45 / 1.5 = "
        "0.4714, so T = (0.4714, -0.8819, 0): bent towards the normal, still going +x and down. "
        "n1 sin(theta1) = n2 sin(theta2) to within 4e-16.");
    const Vec3 d = falling_at(radians(45));
    const std::optional<Vec3> t = refract(d, kUp, 1 / 1.5);
    REQUIRE(t);
    CAPTURE(t->x, t->y, t->z);
    const double sin1 = d.x;
    const double sin2 = t->x;  // |T| = 1, so its tangential part is sin(theta2)
    CHECK_THAT(1.0 * sin1 - 1.5 * sin2, IsNear(0.0, 4e-16));
    CHECK_THAT(std::sqrt(t->x * t->x + t->y * t->y + t->z * t->z), IsNear(1.0, 4e-16));
    CHECK(t->y < 0.0);
    CHECK(t->z == 0.0);
}

TEST_CASE("refract: leaving glass just beyond the critical angle is total internal reflection",
          "[stage9]") {
    INFO(uses("refract", "stage 1's dot"));
    INFO(
        "Inside glass (eta = 1.5 / 1), the critical angle is asin(1 / 1.5) = 41.81 degrees. At 42 "
        "degrees, sin^2(theta2) = 1.5^2 sin^2 42 = 1.007 > 1: no refracted ray, nullopt.");
    const std::optional<Vec3> t = refract(falling_at(radians(42)), kUp, 1.5);
    CHECK_FALSE(t.has_value());
}

TEST_CASE("refract: leaving glass just below the critical angle, a grazing refracted ray",
          "[stage9]") {
    INFO(uses("refract", "stage 1's dot"));
    INFO(
        "At 41.5 degrees, sin(theta2) = 1.5 sin 41.5 = 0.9936: theta2 = 83.5 degrees, almost along "
        "the surface, still below it and still obeying Snell's law.");
    const Vec3 d = falling_at(radians(41.5));
    const std::optional<Vec3> t = refract(d, kUp, 1.5);
    REQUIRE(t);
    CAPTURE(t->x, t->y, t->z);
    CHECK_THAT(1.5 * d.x - 1.0 * t->x, IsNear(0.0, 4e-16));
    CHECK(t->y < 0.0);
    CHECK_THAT(std::sqrt(t->x * t->x + t->y * t->y), IsNear(1.0, 4e-16));
}

TEST_CASE("refract: eta = 1 leaves the direction as it is", "[stage9]") {
    INFO(uses("refract", "stage 1's dot"));
    INFO(
        "The same index on both sides: nothing bends, at any angle. To within 1e-14: near "
        "grazing, cos2 = sqrt(1 - sin^2) loses the ulps of 1 that the subtraction cancels, "
        "divided by cos 89 = 0.017.");
    for (double degrees : {0.0, 30.0, 60.0, 89.0}) {
        CAPTURE(degrees);
        const Vec3 d = falling_at(radians(degrees));
        const std::optional<Vec3> t = refract(d, kUp, 1.0);
        REQUIRE(t);
        REQUIRE_THAT(*t, IsNear(d, 1e-14));
    }
}

TEST_CASE("fresnel_exact: 0.04 head-on from air into glass", "[stage9]") {
    INFO("cos = 1: r_s = (1 - 1.5) / 2.5 = -0.2, r_p = 0.2, F = (0.04 + 0.04) / 2 = 0.04.");
    const double entering = fresnel_exact(1.0, 1.0, 1.5);
    const double leaving = fresnel_exact(1.0, 1.5, 1.0);
    CHECK(entering == Approx(0.04).epsilon(1e-14));
    CHECK(leaving == Approx(0.04).epsilon(1e-14));
}

TEST_CASE("fresnel_exact: 1 at grazing incidence", "[stage9]") {
    INFO("cos = 0: r_s = -n2 cos2 / n2 cos2 = -1, r_p = -1, F = 1.");
    CHECK(fresnel_exact(0.0, 1.0, 1.5) == Approx(1.0).epsilon(1e-14));
}

TEST_CASE("fresnel_exact: 1 beyond the critical angle", "[stage9]") {
    INFO("Leaving glass at 45 degrees (critical angle 41.8): no refracted ray, all reflected.");
    const double at_45 = fresnel_exact(std::cos(radians(45)), 1.5, 1.0);
    const double grazing = fresnel_exact(0.0, 1.5, 1.0);
    CHECK(at_45 == 1.0);
    CHECK(grazing == 1.0);
}

TEST_CASE("fresnel_exact: at Brewster's angle r_p = 0, so F = r_s^2 / 2 = 25/338", "[stage9]") {
    INFO(
        "tan(theta_B) = n2 / n1 = 1.5: cos(theta1) = 1 / sqrt(3.25), and theta1 + theta2 = 90 "
        "degrees, so cos(theta2) = sin(theta1) = 1.5 / sqrt(3.25). r_p = (1.5 cos1 - cos2) / (...) "
        "= 0; r_s = (cos1 - 1.5 cos2) / (cos1 + 1.5 cos2) = (1 - 2.25) / (1 + 2.25) = -5/13; F = "
        "(25/169) / 2 = 25/338 = 0.0739645.");
    CHECK(fresnel_exact(1 / std::sqrt(3.25), 1.0, 1.5) == Approx(25.0 / 338).epsilon(1e-13));
}

TEST_CASE("fresnel_exact: into glass at 60 degrees, the mean of r_s^2 and r_p^2", "[stage9]") {
    INFO(
        "Into glass at 60 degrees: cos1 = 1/2, sin2 = (sqrt 3 / 2) / 1.5 = 1 / sqrt 3, cos2 = "
        "sqrt(2/3); r_s = (1/2 - 1.5 cos2) / (1/2 + 1.5 cos2), r_p = (1.5/2 - cos2) / (1.5/2 + "
        "cos2), F = (r_s^2 + r_p^2) / 2 = 0.0891867.");
    const double cos2 = std::sqrt(2.0 / 3.0);
    const double r_s = (0.5 - 1.5 * cos2) / (0.5 + 1.5 * cos2);
    const double r_p = (0.75 - cos2) / (0.75 + cos2);
    CHECK(fresnel_exact(0.5, 1.0, 1.5) == Approx((r_s * r_s + r_p * r_p) / 2).epsilon(1e-13));
}

TEST_CASE("fresnel_exact: reciprocity, the same F both ways through the surface", "[stage9]") {
    INFO(
        "Light entering glass at theta1 and light leaving it at the matching theta2 (sin theta2 = "
        "sin theta1 / 1.5) are reflected alike: F(1 -> 1.5, cos theta1) = F(1.5 -> 1, cos "
        "theta2). A formula with n1 and n2 or the cosines swapped breaks this.");
    for (double degrees : {10.0, 30.0, 60.0, 75.0, 89.0}) {
        CAPTURE(degrees);
        const double theta1 = radians(degrees);
        const double theta2 = std::asin(std::sin(theta1) / 1.5);
        const double entering = fresnel_exact(std::cos(theta1), 1.0, 1.5);
        const double leaving = fresnel_exact(std::cos(theta2), 1.5, 1.0);
        CAPTURE(entering, leaving);
        REQUIRE(entering == Approx(leaving).epsilon(1e-12));
        REQUIRE(entering > 0.04);
        REQUIRE(entering < 1.0);
    }
}

TEST_CASE("fresnel_schlick: R0 head-on", "[stage9]") {
    INFO("cos = 1: (1 - cos)^5 = 0, F = R0 = ((1 - 1.5) / 2.5)^2 = 0.04, from either side.");
    const double entering = fresnel_schlick(1.0, 1.0, 1.5);
    const double leaving = fresnel_schlick(1.0, 1.5, 1.0);
    CHECK(entering == Approx(0.04).epsilon(1e-14));
    CHECK(leaving == Approx(0.04).epsilon(1e-14));
}

TEST_CASE("fresnel_schlick: 1 under total internal reflection", "[stage9]") {
    INFO("Leaving glass at 45 degrees, beyond the critical angle: 1, as fresnel_exact.");
    CHECK(fresnel_schlick(std::cos(radians(45)), 1.5, 1.0) == 1.0);
}

TEST_CASE("fresnel_schlick: uses the cosine on the less dense side", "[stage9]") {
    INFO(
        "Into glass at 60 degrees: cos = 1/2, F = 0.04 + 0.96 (1/2)^5 = 0.07. Leaving glass at "
        "the matching angle (sin theta1 = sin 60 / 1.5), the cosine to use is the air side's, "
        "cos 60 = 1/2 again: the same 0.07. With the glass side's cosine (0.8165) it would be "
        "0.04 + 0.96 0.1835^5 = 0.0402.");
    const double entering = fresnel_schlick(0.5, 1.0, 1.5);
    const double cos_in_glass = std::sqrt(1 - 1.0 / 3.0);  // sin = (sqrt 3 / 2) / 1.5
    const double leaving = fresnel_schlick(cos_in_glass, 1.5, 1.0);
    CHECK(entering == Approx(0.07).epsilon(1e-14));
    CHECK(leaving == Approx(0.07).epsilon(1e-12));
}
