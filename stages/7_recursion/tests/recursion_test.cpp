// Public tests for stage 7, recursive reflection. Run them with
// `ctest --preset student -L stage7`, or build/student/bin/raystep_stage7_tests.
//
// radiance is tested without a scene: the ShadeFunction here is a lambda that plays the scene
// (two mirrors facing each other, a single surface, nothing at all), records the rays it is
// asked about and counts the calls. Each test calls your function before its CHECKs, so a stub
// is reported once. A function built from others names them when it fails: fix theirs first.

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "base/testing/catch.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/7_recursion/recursion.h"

using namespace raystep;
using raystep::testing::IsNear;
using raystep::testing::uses;

namespace {

const double kInf = std::numeric_limits<double>::infinity();

const RayOffset kErrorBound{OffsetRule::error_bound, 0.0};

// What the fake scenes return, everywhere: every colour channel a power of two, so that the
// sums below are exact and == is fair.
const Color kLocal{1, 0.5, 0.25};

// Two mirrors facing each other: the plane z = 0 (normal +z) and the plane z = 1 (normal -z),
// each with local colour kLocal and the given reflectance. A ray going up hits z = 1, a ray going
// down hits z = 0; a ray parallel to them leaves the scene. Every ray asked about is recorded.
ShadeFunction facing_mirrors(const Color& reflectance, std::vector<Ray>& asked) {
    return [reflectance, &asked](const Ray& ray) -> std::optional<ShadedHit> {
        asked.push_back(ray);
        if (ray.direction.z == 0.0) return std::nullopt;
        const double plane_z = ray.direction.z > 0.0 ? 1.0 : 0.0;
        const double t = (plane_z - ray.origin.z) / ray.direction.z;
        const Vec3 normal{0, 0, ray.direction.z > 0.0 ? -1.0 : 1.0};
        const SurfacePoint point{ray.at(t), Vec3(1e-16), normal, normal, -ray.direction};
        return ShadedHit{point, kLocal, reflectance};
    };
}

// A scene where the first ray hits a mirror on the floor and everything after it misses.
ShadeFunction mirror_then_sky(std::vector<Ray>& asked) {
    return [&asked](const Ray& ray) -> std::optional<ShadedHit> {
        asked.push_back(ray);
        if (asked.size() > 1) return std::nullopt;
        const Vec3 up{0, 0, 1};
        const SurfacePoint point{{0, 0, 0}, Vec3(1e-16), up, up, -ray.direction};
        return ShadedHit{point, kLocal, Color(0.5)};
    };
}

const Ray kUpward{{0, 0, 0.5}, {0, 0, 1}};

}  // namespace

TEST_CASE("radiance: a ray that misses everything is black", "[stage7]") {
    INFO(uses("radiance", "reflected_ray"));
    int calls = 0;
    const ShadeFunction nothing = [&calls](const Ray&) -> std::optional<ShadedHit> {
        ++calls;
        return std::nullopt;
    };
    const Color got = radiance(nothing, kUpward, 5, kErrorBound);
    CHECK(got == Color(0.0));
    CHECK(calls == 1);
}

TEST_CASE("radiance: a surface that is no mirror shows its local colour, no mirror ray traced",
          "[stage7]") {
    INFO(uses("radiance", "reflected_ray"));
    INFO("Reflectance 0: the reflected ray would add 0 * whatever, so it must not cost a ray.");
    std::vector<Ray> asked;
    const Color got = radiance(facing_mirrors(Color(0.0), asked), kUpward, 5, kErrorBound);
    CHECK(got == kLocal);
    CHECK(asked.size() == 1);
}

TEST_CASE("radiance: with no bounce left, the mirror ray is not traced", "[stage7]") {
    INFO(uses("radiance", "reflected_ray"));
    INFO("bounces_left = 0 (maxdepth 0): the mirror shows its local colour only, one call.");
    std::vector<Ray> asked;
    const Color got = radiance(facing_mirrors(Color(0.5), asked), kUpward, 0, kErrorBound);
    CHECK(got == kLocal);
    CHECK(asked.size() == 1);
}

TEST_CASE("radiance: facing mirrors, reflectance 0.5, maxdepth 3: local (1 + 0.5 + 0.25 + 0.125)",
          "[stage7]") {
    INFO(uses("radiance", "reflected_ray"));
    INFO(
        "The eye ray and 3 bounces: I = c + 0.5 (c + 0.5 (c + 0.5 c)) = 1.875 c, with c = (1, 0.5, "
        "0.25): (1.875, 0.9375, 0.46875), exact in binary. 4 calls, the rays going up, down, up, "
        "down.");
    std::vector<Ray> asked;
    const Color got = radiance(facing_mirrors(Color(0.5), asked), kUpward, 3, kErrorBound);
    CHECK(got == Color(1.875, 0.9375, 0.46875));
    REQUIRE(asked.size() == 4);
    for (std::size_t k = 0; k < asked.size(); ++k) {
        CAPTURE(k);
        REQUIRE_THAT(asked[k].direction, IsNear(Vec3{0, 0, k % 2 == 0 ? 1.0 : -1.0}, 1e-15));
    }
}

TEST_CASE("radiance: the reflectance weighs each colour channel", "[stage7]") {
    INFO(uses("radiance", "reflected_ray"));
    INFO(
        "One bounce with reflectance (1, 0.5, 0): I = c + (1, 0.5, 0) c = (1 + 1, 0.5 + 0.25, 0.25 "
        "+ 0) = (2, 0.75, 0.25). Not clamped: the image does that.");
    std::vector<Ray> asked;
    const Color got = radiance(facing_mirrors({1, 0.5, 0}, asked), kUpward, 1, kErrorBound);
    CHECK(got == Color(2, 0.75, 0.25));
    CHECK(asked.size() == 2);
}

TEST_CASE("radiance: a faint mirror is still a mirror: only an exactly black Ks stops it",
          "[stage7]") {
    INFO(uses("radiance", "reflected_ray"));
    INFO(
        "Reflectance 2^-8 = 0.00390625 is not black: one bounce adds c / 256, exact in binary. A "
        "cutoff \"for speed\" (say max(Ks) < 0.01) would drop the reflection and the second ray.");
    std::vector<Ray> asked;
    const Color faint(0.00390625);
    const Color got = radiance(facing_mirrors(faint, asked), kUpward, 1, kErrorBound);
    CHECK(got == kLocal + faint * kLocal);
    CHECK(asked.size() == 2);
}

TEST_CASE("radiance: a mirror ray that leaves the scene adds black", "[stage7]") {
    INFO(uses("radiance", "reflected_ray"));
    std::vector<Ray> asked;
    const Color got = radiance(mirror_then_sky(asked), {{0, 0, 1}, {0, 0, -1}}, 5, kErrorBound);
    CHECK(got == kLocal);
    CHECK(asked.size() == 2);
}

TEST_CASE("radiance: mirror rays leave the surface by the offset rule it is given", "[stage7]") {
    INFO(uses("radiance", "reflected_ray"));
    INFO(
        "The mirror at the origin, the eye ray coming straight down: with along_ray and epsilon "
        "0.125, the mirror ray starts at the hit point, goes straight up, counts hits from t = "
        "0.125 and is unbounded.");
    std::vector<Ray> asked;
    const RayOffset along_ray{OffsetRule::along_ray, 0.125};
    radiance(mirror_then_sky(asked), {{0, 0, 1}, {0, 0, -1}}, 5, along_ray);
    REQUIRE(asked.size() == 2);
    CHECK(asked[1].origin == Vec3(0, 0, 0));
    CHECK_THAT(asked[1].direction, IsNear(Vec3{0, 0, 1}, 1e-15));
    CHECK(asked[1].t_min == 0.125);
    CHECK(asked[1].t_max == kInf);
}

TEST_CASE("reflected_ray: 45-degree incidence leaves at 45 degrees on the other side", "[stage7]") {
    INFO(uses("reflected_ray", "stage 1's reflect, stage 6's spawn_ray"));
    INFO(
        "The floor y = 0 at (2, 0, 1), normal +y, the eye up and to the left: V = (-1, 1, 0)/sqrt "
        "2. The ray came in along -V = (1, -1, 0)/sqrt 2, and d - 2 (d . n) n flips its y: R = (1, "
        "1, 0)/sqrt 2. along_normal with epsilon 0.25: origin (2, 0.25, 1), t from 0 on.");
    const double h = 1 / std::sqrt(2.0);
    const SurfacePoint point{{2, 0, 1}, Vec3(0.0), {0, 1, 0}, {0, 1, 0}, {-h, h, 0}};
    const Ray ray = reflected_ray(point, {OffsetRule::along_normal, 0.25});
    CHECK_THAT(ray.direction, IsNear(Vec3{h, h, 0}, 1e-15));
    CHECK(ray.origin == Vec3(2, 0.25, 1));
    CHECK(ray.t_min == 0.0);
    CHECK(ray.t_max == kInf);
}

TEST_CASE("reflected_ray: reflects about the shading normal, not the geometric one", "[stage7]") {
    INFO(uses("reflected_ray", "stage 1's reflect, stage 6's spawn_ray"));
    INFO(
        "Seen from straight above, V = (0, 1, 0), with an interpolated normal N = (0, 0.8, 0.6): "
        "-V = (0, -1, 0), -V . N = -0.8, R = (0, -1, 0) + 1.6 (0, 0.8, 0.6) = (0, 0.28, 0.96). "
        "About the geometric normal (0, 1, 0) it would go straight back up.");
    const SurfacePoint point{{0, 0, 0}, Vec3(0.0), {0, 1, 0}, {0, 0.8, 0.6}, {0, 1, 0}};
    const Ray ray = reflected_ray(point, {OffsetRule::along_ray, 0.125});
    CHECK_THAT(ray.direction, IsNear(Vec3{0, 0.28, 0.96}, 1e-15));
}

TEST_CASE("reflected_ray: with error_bound, starts beyond the point's error on the mirror's side",
          "[stage7]") {
    INFO(uses("reflected_ray", "stage 1's reflect, stage 6's spawn_ray"));
    INFO(
        "Error 1e-9 in y on the floor y = 0: the mirror ray must start above y = 1e-9, so that it "
        "cannot find the floor again at t ~ 0.");
    const double h = 1 / std::sqrt(2.0);
    const SurfacePoint point{{2, 0, 1}, {0, 1e-9, 0}, {0, 1, 0}, {0, 1, 0}, {-h, h, 0}};
    const Ray ray = reflected_ray(point, kErrorBound);
    CHECK(ray.origin.y > 1e-9);
    CHECK(ray.origin.x == 2.0);
    CHECK(ray.origin.z == 1.0);
    CHECK(ray.t_min == 0.0);
    CHECK(ray.t_max == kInf);
}
