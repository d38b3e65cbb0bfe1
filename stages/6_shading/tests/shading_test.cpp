// Public tests for stage 6, lights and the local model. Run them with
// `ctest --preset student -L stage6`, or run build/student/bin/raystep_stage6_tests to see every
// failure in full.
//
// Each test calls your function before its CHECKs: an exception outside a CHECK ends the test at
// once, so a stub is reported once. The comments give the arithmetic, so you can redo it by hand.
// A function built from others names them when it fails: fix theirs first.

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "base/testing/catch.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/6_shading/shading.h"

using namespace raystep;
using raystep::testing::IsNear;
using raystep::testing::uses;

namespace {

const double kInf = std::numeric_limits<double>::infinity();
constexpr double kTight = 1e-15;  // a few ulps of the values these tests use

// A point on the floor z = 0 at the origin, normal +z, seen from `to_eye`.
SurfacePoint on_floor(const Vec3& to_eye) {
    return {{0, 0, 0}, {0, 0, 0}, {0, 0, 1}, {0, 0, 1}, to_eye};
}

Material material(const Color& diffuse, const Color& specular, double shininess) {
    Material m;
    m.ambient = Color(0.0);
    m.diffuse = diffuse;
    m.specular = specular;
    m.shininess = shininess;
    return m;
}

LightSample white_light_from(const Vec3& direction) {
    return {direction, 10.0, Color(1.0)};
}

}  // namespace

TEST_CASE("attenuation: constant + linear d + quadratic d^2 at several distances", "[stage6]") {
    INFO("Every number here is exact in binary, so == is fair.");
    const Attenuation falloff{0.5, 0.25, 0.125};
    const double at_0 = attenuation(falloff, 0.0);
    const double at_2 = attenuation(falloff, 2.0);
    const double at_4 = attenuation(falloff, 4.0);
    const double at_10 = attenuation(falloff, 10.0);
    CHECK(at_0 == 0.5);    // 0.5 + 0 + 0
    CHECK(at_2 == 1.5);    // 0.5 + 0.25 * 2 + 0.125 * 4   = 0.5 + 0.5 + 0.5
    CHECK(at_4 == 3.5);    // 0.5 + 0.25 * 4 + 0.125 * 16  = 0.5 + 1 + 2
    CHECK(at_10 == 15.5);  // 0.5 + 0.25 * 10 + 0.125 * 100 = 0.5 + 2.5 + 12.5
}

TEST_CASE("attenuation: the default (1, 0, 0) is 1 at every distance, and (0, 0, 1) is d^2",
          "[stage6]") {
    const double none_near = attenuation(Attenuation{}, 0.0);
    const double none_far = attenuation(Attenuation{}, 1e6);
    const double inverse_square = attenuation(Attenuation{0, 0, 1}, 3.0);
    CHECK(none_near == 1.0);
    CHECK(none_far == 1.0);
    CHECK(inverse_square == 9.0);
}

TEST_CASE("sample_light: a point light 5 away gives its unit direction, distance and dimmed colour",
          "[stage6]") {
    INFO(uses("sample_light", "attenuation and stage 1's length and normalize"));
    INFO(
        "From (1, 1, 1) to the light at (1, 4, 5): (0, 3, 4), of length 5, so L = (0, 0.6, 0.8). "
        "Inverse-square falloff: att = 5^2 = 25, intensity = (1, 0.5, 0.25) / 25.");
    const PointLight light{{1, 4, 5}, {1, 0.5, 0.25}, {0, 0, 1}};
    const LightSample sample = sample_light(light, {1, 1, 1});
    CHECK_THAT(sample.direction, IsNear(Vec3{0, 0.6, 0.8}, kTight));
    CHECK(sample.distance == Approx(5.0).epsilon(kTight));
    CHECK_THAT(sample.intensity, IsNear(Color{0.04, 0.02, 0.01}, kTight));
}

TEST_CASE("sample_light: a point light with the default attenuation keeps its colour", "[stage6]") {
    INFO(uses("sample_light", "attenuation and stage 1's length and normalize"));
    INFO("att = 1 + 0 d + 0 d^2 = 1: the colour, unchanged, 13 away ((3, 4, 12) has length 13).");
    const PointLight light{{3, 4, 12}, {0.5, 0.25, 1}, {}};
    const LightSample sample = sample_light(light, {0, 0, 0});
    CHECK_THAT(sample.direction, IsNear(Vec3{3, 4, 12} / 13.0, kTight));
    CHECK(sample.distance == Approx(13.0).epsilon(kTight));
    CHECK(sample.intensity == Color(0.5, 0.25, 1));
}

TEST_CASE("sample_light: a point exactly at a point light throws std::domain_error", "[stage6]") {
    INFO(uses("sample_light", "attenuation and stage 1's length and normalize"));
    INFO("There is no direction from the light to itself: an error, never a NaN direction.");
    const PointLight light{{1, 2, 3}, {1, 1, 1}, {}};
    REQUIRE_THROWS_AS(sample_light(light, {1, 2, 3}), std::domain_error);
}

TEST_CASE("sample_light: a directional light is infinitely far, never attenuated, unit direction",
          "[stage6]") {
    INFO(uses("sample_light", "attenuation and stage 1's length and normalize"));
    INFO("(3, 0, 4) has length 5: L = (0.6, 0, 0.8).");
    const DirectionalLight light{{3, 0, 4}, {0.5, 0.25, 1}};
    const LightSample sample = sample_light(light);
    CHECK_THAT(sample.direction, IsNear(Vec3{0.6, 0, 0.8}, kTight));
    CHECK(sample.distance == kInf);
    CHECK(sample.intensity == Color(0.5, 0.25, 1));
}

TEST_CASE("blinn_phong: a light 60 degrees from the normal gives half the diffuse colour",
          "[stage6]") {
    INFO(uses("blinn_phong", "stage 1's dot and normalize"));
    INFO(
        "Lambert: N . L = cos 60 = 0.5 for L = (sin 60, 0, cos 60) = (sqrt(3)/2, 0, 0.5), so I = 1 "
        "* Kd * 0.5 = (0.8, 0.4, 0.2) * 0.5. No specular (Ks = 0).");
    const Vec3 l{std::sqrt(3.0) / 2.0, 0, 0.5};
    const Color got = blinn_phong(material({0.8, 0.4, 0.2}, Color(0.0), 1.0), on_floor({0, 0, 1}),
                                  white_light_from(l));
    CHECK_THAT(got, IsNear(Color{0.4, 0.2, 0.1}, kTight));
}

TEST_CASE("blinn_phong: the highlight is max(N . H, 0)^s with the half vector H = normalize(L + V)",
          "[stage6]") {
    INFO(uses("blinn_phong", "stage 1's dot and normalize"));
    INFO(
        "N = (0, 0, 1), L = (0, 0.6, 0.8), V = (0, 0, 1). L + V = (0, 0.6, 1.8), of squared length "
        "0.36 + 3.24 = 3.6, so N . H = 1.8 / sqrt(3.6) and (N . H)^2 = 3.24 / 3.6 = 0.9. With s = "
        "10: (N . H)^10 = 0.9^5 = 0.59049; Ks = (1, 0.5, 0), Kd = 0. (Unnormalized, N . (L + V) = "
        "1.8 and 1.8^10 = 357; Phong's R . V = 0.8 gives 0.107.)");
    const Color got = blinn_phong(material(Color(0.0), {1, 0.5, 0}, 10.0), on_floor({0, 0, 1}),
                                  white_light_from({0, 0.6, 0.8}));
    CHECK_THAT(got, IsNear(Color{0.59049, 0.295245, 0}, 1e-14));
}

TEST_CASE("blinn_phong: diffuse and specular add, and the light's intensity scales both",
          "[stage6]") {
    INFO(uses("blinn_phong", "stage 1's dot and normalize"));
    INFO(
        "The geometry of the highlight test: N . L = 0.8 and (N . H)^10 = 0.59049. Kd = Ks = 0.5: "
        "0.5 * 0.8 + 0.5 * 0.59049 = 0.4 + 0.295245 = 0.695245 per channel, times the intensity "
        "(1, 0.5, 2): (0.695245, 0.3476225, 1.39049).");
    const LightSample light{{0, 0.6, 0.8}, 10.0, {1, 0.5, 2}};
    const Color got =
        blinn_phong(material(Color(0.5), Color(0.5), 10.0), on_floor({0, 0, 1}), light);
    CHECK_THAT(got, IsNear(Color{0.695245, 0.3476225, 1.39049}, 1e-14));
}

TEST_CASE("blinn_phong: a light behind the surface adds nothing, no highlight through the back",
          "[stage6]") {
    INFO(uses("blinn_phong", "stage 1's dot and normalize"));
    INFO(
        "L = (0, 0.6, -0.8): N . L = -0.8. The half vector of L and V = (0, 0, 1) is normalize(0, "
        "0.6, 0.2), with N . H = 0.32 > 0: without the N . L test, a highlight shows through the "
        "back of the surface.");
    const Color got = blinn_phong(material(Color(1.0), Color(1.0), 1.0), on_floor({0, 0, 1}),
                                  white_light_from({0, 0.6, -0.8}));
    CHECK(got == Color(0.0));
}

TEST_CASE("blinn_phong: a light in the tangent plane (N . L = 0) adds nothing, shininess 0 too",
          "[stage6]") {
    INFO(uses("blinn_phong", "stage 1's dot and normalize"));
    INFO(
        "L = (1, 0, 0) grazes the floor: N . L = 0, so no light, and no highlight either, although "
        "N . H = 1 / sqrt(2) and max(N . H, 0)^0 would be 1.");
    const Color got = blinn_phong(material(Color(1.0), Color(1.0), 0.0), on_floor({0, 0, 1}),
                                  white_light_from({1, 0, 0}));
    CHECK(got == Color(0.0));
}

TEST_CASE("blinn_phong: lights with the shading normal, not the geometric one", "[stage6]") {
    INFO(uses("blinn_phong", "stage 1's dot and normalize"));
    INFO(
        "An interpolated normal N = (0, 0.6, 0.8) on the floor: L = (0, 0.6, 0.8) is along it, so "
        "N . L = 1 and I = Kd. The geometric normal (0, 0, 1) would give N . L = 0.8.");
    SurfacePoint point = on_floor({0, 0, 1});
    point.shading_normal = {0, 0.6, 0.8};
    const Color got = blinn_phong(material({0.5, 0.25, 1}, Color(0.0), 1.0), point,
                                  white_light_from({0, 0.6, 0.8}));
    CHECK_THAT(got, IsNear(Color{0.5, 0.25, 1}, kTight));
}

TEST_CASE("blinn_phong: shininess 0 makes max(N . H, 0)^0 = 1, also where N . H = 0", "[stage6]") {
    INFO(uses("blinn_phong", "stage 1's dot and normalize"));
    INFO(
        "pow(0, 0) is 1 here (as std::pow has it). To get N . H = 0 with N . L > 0, the eye must "
        "be behind the shading normal, as an interpolated normal allows: N = (0, 0, 1) (geometric "
        "normal (0.8, 0, 0.6), so N_geometric . V = 0.28 > 0), L = (0, 0.8, 0.6), V = (0.8, 0, "
        "-0.6): L + V = (0.8, 0.8, 0), so N . H = 0 exactly, and N . L = 0.6.");
    SurfacePoint point = on_floor({0.8, 0, -0.6});
    point.normal = {0.8, 0, 0.6};
    const LightSample light = white_light_from({0, 0.8, 0.6});

    // Kd = 0, Ks = (0.25, 0.5, 1): the highlight is Ks * 0^0 = Ks.
    const Color highlight = blinn_phong(material(Color(0.0), {0.25, 0.5, 1}, 0.0), point, light);
    CHECK_THAT(highlight, IsNear(Color{0.25, 0.5, 1}, kTight));

    // Ks = 0 with shininess 0, common in CSE167 scenes: 0 * 0^0 = 0, the diffuse 0.6 alone
    // (a NaN for 0^0 would turn the pixel black).
    const Color matte = blinn_phong(material(Color(1.0), Color(0.0), 0.0), point, light);
    CHECK_THAT(matte, IsNear(Color(0.6), kTight));
}

TEST_CASE("blinn_phong: no highlight where N . H < 0, whatever the shininess", "[stage6]") {
    INFO(uses("blinn_phong", "stage 1's dot and normalize"));
    INFO(
        "The eye behind an interpolated normal N = (0.8, 0, 0.6) on the floor (the geometric "
        "normal (0, 0, 1) faces V = (-0.96, 0, 0.28)): L = (-0.28, 0, 0.96) gives N . L = 0.352 > "
        "0, but N . (L + V) = 0.8 (-1.24) + 0.6 (1.24) = -0.248, so N . H < 0 and max(N . H, 0)^s "
        "= 0. Only the diffuse term is left: 0.5 * 0.352 = 0.176. Without the max, (N . H)^2 would "
        "add a highlight and (N . H)^0.5 would be NaN.");
    SurfacePoint point = on_floor({-0.96, 0, 0.28});
    point.shading_normal = {0.8, 0, 0.6};
    const LightSample light = white_light_from({-0.28, 0, 0.96});
    for (const double shininess : {2.0, 0.5}) {
        CAPTURE(shininess);
        const Color got = blinn_phong(material(Color(0.5), Color(1.0), shininess), point, light);
        REQUIRE_THAT(got, IsNear(Color(0.176), kTight));
    }
}

TEST_CASE("blinn_phong: the eye exactly opposite the light has no half vector, N . H counts as 0",
          "[stage6]") {
    INFO(uses("blinn_phong", "stage 1's dot and normalize"));
    INFO(
        "The bent normal of the test above, N = (0.8, 0, 0.6), V = (-0.96, 0, 0.28), with the "
        "light at L = -V = (0.96, 0, -0.28): N . L = 0.768 - 0.168 = 0.6 > 0, but L + V = 0, and "
        "normalize(L + V) has nothing to divide by. No direction lies halfway: N . H counts as 0, "
        "so shininess 8 leaves the diffuse 0.5 * 0.6 = 0.3, and shininess 0 adds Ks (0^0 = 1).");
    SurfacePoint point = on_floor({-0.96, 0, 0.28});
    point.shading_normal = {0.8, 0, 0.6};
    const LightSample light = white_light_from({0.96, 0, -0.28});
    const Color shiny = blinn_phong(material(Color(0.5), Color(1.0), 8.0), point, light);
    CHECK_THAT(shiny, IsNear(Color(0.3), kTight));
    const Color flat = blinn_phong(material(Color(0.5), {0.25, 0.5, 1}, 0.0), point, light);
    CHECK_THAT(flat, IsNear(Color{0.55, 0.8, 1.3}, kTight));
}

TEST_CASE("local_shading: ambient + emission + each visible light's term", "[stage6]") {
    INFO(uses("local_shading", "blinn_phong"));
    INFO(
        "A = (0.1, 0.2, 0.3), E = (0.2, 0, 0), Kd = 0.5, Ks = 0. Light 1 straight above: N . L = "
        "1, term 0.5 * 1 * (1, 1, 1) = (0.5, 0.5, 0.5). Light 2 at 60 degrees: N . L = 0.5, term "
        "0.5 * 0.5 * (0.2, 0.4, 0.8) = (0.05, 0.1, 0.2). Sum: (0.1 + 0.2 + 0.5 + 0.05, 0.2 + 0 + "
        "0.5 + 0.1, 0.3 + 0 + 0.5 + 0.2) = (0.85, 0.8, 1).");
    Material m = material(Color(0.5), Color(0.0), 1.0);
    m.ambient = {0.1, 0.2, 0.3};
    m.emission = {0.2, 0, 0};
    const std::vector<LightSample> lights{
        {{0, 0, 1}, 10.0, {1, 1, 1}},
        {{std::sqrt(3.0) / 2.0, 0, 0.5}, kInf, {0.2, 0.4, 0.8}},
    };
    const Color got = local_shading(m, on_floor({0, 0, 1}), lights);
    CHECK_THAT(got, IsNear(Color{0.85, 0.8, 1}, kTight));
}

TEST_CASE("local_shading: where no light reaches, ambient + emission remain", "[stage6]") {
    INFO(uses("local_shading", "blinn_phong"));
    INFO("In full shadow the visible list is empty: I = A + E = (0.1, 0.2, 0.3) + (0.5, 0.25, 0).");
    Material m = material(Color(1.0), Color(1.0), 8.0);
    m.ambient = {0.1, 0.2, 0.3};
    m.emission = {0.5, 0.25, 0};
    const Color got = local_shading(m, on_floor({0, 0, 1}), {});
    CHECK_THAT(got, IsNear(Color{0.6, 0.45, 0.3}, kTight));
}
