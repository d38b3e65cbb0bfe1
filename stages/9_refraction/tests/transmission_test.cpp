// Public tests for stage 9, the refracted ray and radiance through glass. Run them with
// `ctest --preset student -L stage9`, one function's with
// `build/student/bin/raystep_stage9_tests "radiance_with_refraction:*"`.
//
// radiance_with_refraction is tested without a scene, as stage 7's radiance is: the
// MediumShadeFunction here is a lambda that plays the scene (a glass surface, a slab of glass,
// a sky above and a floor below), records the rays it is asked about and counts the calls. A
// made-up index of 3 makes F exactly 1/4 head-on ((3 - 1) / (3 + 1) = 1/2, squared), so that
// the colours below are sums of powers of two and == is fair. Each test calls your function
// before its CHECKs: a stub is reported once. A loop over cases stops at the first that fails,
// and a function built from others names them: fix theirs first.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/9_refraction/refraction.h"

using namespace raystep;
using raystep::testing::IsNear;
using raystep::testing::uses;

namespace {

const double kInf = std::numeric_limits<double>::infinity();

const RayOffset kAlongNormal{OffsetRule::along_normal, 0.125};

// What the sky above (rays going up) and the floor below (rays going down) show: opaque, and
// no two channels alike, so that each weight shows in the sum.
const Color kSky{1, 2, 0};
const Color kFloor{0, 1, 2};

// A glass surface, as the renderer would report it: the point on the plane through `position`
// with `normal` turned towards the ray, its transmission and mirror colours, and the solid.
MediumHit glass(const Ray& ray, const Vec3& normal, double index, bool entering,
                const Color& transmission, const Color& reflectance, const Color& local) {
    const double t = -(ray.origin.z) / ray.direction.z;  // every glass surface here is z = 0
    const SurfacePoint point{ray.at(t), Vec3(0.0), normal, normal, -ray.direction};
    return {ShadedHit{point, local, reflectance}, transmission, Medium{7, index}, entering};
}

// An opaque surface across the ray: its colour, no mirror, no glass.
MediumHit opaque(const Ray& ray, const Color& local) {
    const Vec3 normal{0, 0, ray.direction.z > 0 ? -1.0 : 1.0};
    const SurfacePoint point{ray.origin + ray.direction, Vec3(0.0), normal, normal, -ray.direction};
    return {ShadedHit{point, local, Color(0.0)}, Color(0.0), Medium{0, 1.0}, true};
}

// The first ray meets `first`; every later ray sees the sky going up and the floor going down.
MediumShadeFunction glass_then_sky_and_floor(const MediumShadeFunction& first,
                                             std::vector<Ray>& asked) {
    return [first, &asked](const Ray& ray) -> std::optional<MediumHit> {
        asked.push_back(ray);
        if (asked.size() == 1) return first(ray);
        if (ray.direction.z == 0.0) return std::nullopt;
        return opaque(ray, ray.direction.z > 0 ? kSky : kFloor);
    };
}

// A slab of glass of index 3 between z = -1 and z = 0, clear (Kt = 1, Ks = 0, local black),
// with the sky above it and the floor below it. A ray going down from above z = 0 enters it at
// the top; from inside it, leaves by the bottom; going up from inside, leaves by the top.
MediumShadeFunction glass_slab(std::vector<Ray>& asked) {
    return [&asked](const Ray& ray) -> std::optional<MediumHit> {
        asked.push_back(ray);
        const double dz = ray.direction.z;
        const double z = ray.origin.z;
        const Color clear(1.0);
        if (dz < 0 && z > 0) return glass(ray, {0, 0, 1}, 3, true, clear, Color(0.0), Color(0.0));
        if (dz < 0 && z > -1) {
            Ray shifted = ray;  // the bottom, z = -1, as the plane z = 0 one unit down
            shifted.origin.z += 1;
            MediumHit hit = glass(shifted, {0, 0, 1}, 3, false, clear, Color(0.0), Color(0.0));
            hit.shaded.point.position.z -= 1;
            return hit;
        }
        if (dz > 0 && z < 0 && z > -1) {
            return glass(ray, {0, 0, -1}, 3, false, clear, Color(0.0), Color(0.0));
        }
        if (dz == 0.0) return std::nullopt;
        return opaque(ray, dz > 0 ? kSky : kFloor);
    };
}

const Ray kDown{{0, 0, 2}, {0, 0, -1}};

}  // namespace

TEST_CASE("refracted_ray: 45 degrees into glass, on the far side, unbounded", "[stage9]") {
    INFO(uses("refracted_ray", "refract and stage 6's spawn_ray"));
    INFO(
        "The floor y = 0 at the origin, the ray falling at 45 degrees (V = (-sin 45, cos 45, 0)), "
        "air above (n1 = 1), glass below (n2 = 1.5): sin(theta2) = sin 45 / 1.5. along_normal "
        "with epsilon 0.25 starts it 0.25 below the floor, on the side it leaves to: (0, -0.25, "
        "0), t over [0, infinity).");
    const double h = 1 / std::sqrt(2.0);
    const SurfacePoint point{{0, 0, 0}, Vec3(0.0), {0, 1, 0}, {0, 1, 0}, {-h, h, 0}};
    const std::optional<Ray> ray = refracted_ray(point, 1.0, 1.5, {OffsetRule::along_normal, 0.25});
    REQUIRE(ray);
    CHECK(ray->origin == Vec3(0, -0.25, 0));
    CHECK(ray->t_min == 0.0);
    CHECK(ray->t_max == kInf);
    CHECK_THAT(ray->direction.x, IsNear(h / 1.5, 4e-16));
    CHECK(ray->direction.y < 0.0);
}

TEST_CASE("refracted_ray: with error_bound, starts beyond the point's error on the far side",
          "[stage9]") {
    INFO(uses("refracted_ray", "refract and stage 6's spawn_ray"));
    INFO(
        "Error 1e-9 in y on the floor y = 0, the ray going into it head-on: the refracted ray "
        "must start below y = -1e-9, so that it cannot find the floor again at t ~ 0.");
    const SurfacePoint point{{2, 0, 1}, {0, 1e-9, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    const std::optional<Ray> ray = refracted_ray(point, 1.0, 1.5, {OffsetRule::error_bound, 0.0});
    REQUIRE(ray);
    CHECK(ray->origin.y < -1e-9);
    CHECK(ray->origin.x == 2.0);
    CHECK(ray->origin.z == 1.0);
    CHECK_THAT(ray->direction, IsNear(Vec3{0, -1, 0}, 1e-15));
}

TEST_CASE("refracted_ray: bends about the shading normal", "[stage9]") {
    INFO(uses("refracted_ray", "refract and stage 6's spawn_ray"));
    INFO(
        "Seen from straight above (V = (0, 1, 0)) with a shading normal N = (0, 0.8, 0.6), into "
        "glass: cos1 = 0.8, sin^2(theta2) = (1 - 0.64) / 2.25 = 0.16, cos2 = sqrt(0.84), and T = "
        "D / 1.5 + (0.8 / 1.5 - sqrt 0.84) N. About the geometric normal it would go straight "
        "down.");
    const SurfacePoint point{{0, 0, 0}, Vec3(0.0), {0, 1, 0}, {0, 0.8, 0.6}, {0, 1, 0}};
    const std::optional<Ray> ray = refracted_ray(point, 1.0, 1.5, kAlongNormal);
    REQUIRE(ray);
    const Vec3 expected = Vec3{0, -1, 0} / 1.5 + (0.8 / 1.5 - std::sqrt(0.84)) * Vec3{0, 0.8, 0.6};
    CHECK_THAT(ray->direction, IsNear(expected, 1e-15));
}

TEST_CASE("refracted_ray: nullopt under total internal reflection", "[stage9]") {
    INFO(uses("refracted_ray", "refract and stage 6's spawn_ray"));
    INFO("Leaving glass (1.5 -> 1) at 60 degrees, beyond the critical angle of 41.8.");
    const SurfacePoint point{
        {0, 0, 0}, Vec3(0.0), {0, 1, 0}, {0, 1, 0}, {-std::sqrt(3.0) / 2, 0.5, 0}};
    CHECK_FALSE(refracted_ray(point, 1.5, 1.0, kAlongNormal).has_value());
}

TEST_CASE("radiance_with_refraction: a ray that misses everything is black", "[stage9]") {
    INFO(uses("radiance_with_refraction",
              "refracted_ray, the fresnel_ and media functions, stage 7"));
    int calls = 0;
    const MediumShadeFunction nothing = [&calls](const Ray&) -> std::optional<MediumHit> {
        ++calls;
        return std::nullopt;
    };
    const Color got = radiance_with_refraction(nothing, kDown, 5, {}, false, kAlongNormal);
    CHECK(got == Color(0.0));
    CHECK(calls == 1);
}

TEST_CASE("radiance_with_refraction: weights Ks + Kt F on the reflection, Kt (1 - F) through",
          "[stage9]") {
    INFO(uses("radiance_with_refraction",
              "refracted_ray, the fresnel_ and media functions, stage 7"));
    INFO(
        "Head-on into index 3: F = 1/4 (exact and Schlick alike). Ks = (0.5, 0, 0), Kt = (1, 1, "
        "0.5), local (0.25, 0.25, 0.25): reflected weight (0.75, 0.25, 0.125) on the sky (1, 2, "
        "0), refracted weight (0.75, 0.75, 0.375) on the floor (0, 1, 2): I = (1, 1.5, 1). With "
        "F applied twice, F^2 = 1/16 and (1 - F)^2 = 9/16 would show instead.");
    for (bool schlick : {false, true}) {
        CAPTURE(schlick);
        std::vector<Ray> asked;
        const MediumShadeFunction top = [](const Ray& ray) -> std::optional<MediumHit> {
            return glass(ray, {0, 0, 1}, 3, true, {1, 1, 0.5}, {0.5, 0, 0}, Color(0.25));
        };
        const Color got = radiance_with_refraction(glass_then_sky_and_floor(top, asked), kDown, 1,
                                                   {}, schlick, kAlongNormal);
        REQUIRE(got == Color(1, 1.5, 1));
        REQUIRE(asked.size() == 3);
        const auto up = std::count_if(asked.begin() + 1, asked.end(),
                                      [](const Ray& ray) { return ray.direction.z > 0; });
        REQUIRE(up == 1);
    }
}

TEST_CASE("radiance_with_refraction: the refracted ray starts below the glass", "[stage9]") {
    INFO(uses("radiance_with_refraction",
              "refracted_ray, the fresnel_ and media functions, stage 7"));
    INFO(
        "Head-on into the glass at the origin, along_normal with epsilon 0.125: the refracted ray "
        "starts at (0, 0, -0.125), goes straight down and is unbounded; the reflected one starts "
        "at (0, 0, 0.125) and goes up.");
    std::vector<Ray> asked;
    const MediumShadeFunction top = [](const Ray& ray) -> std::optional<MediumHit> {
        return glass(ray, {0, 0, 1}, 3, true, Color(1.0), Color(0.0), Color(0.0));
    };
    radiance_with_refraction(glass_then_sky_and_floor(top, asked), kDown, 1, {}, false,
                             kAlongNormal);
    REQUIRE(asked.size() == 3);
    for (std::size_t k = 1; k < asked.size(); ++k) {
        CAPTURE(k);
        const Ray& ray = asked[k];
        const bool going_up = ray.direction.z > 0;
        REQUIRE(ray.origin == Vec3(0, 0, going_up ? 0.125 : -0.125));
        REQUIRE_THAT(ray.direction, IsNear(Vec3{0, 0, going_up ? 1.0 : -1.0}, 1e-15));
        REQUIRE(ray.t_max == kInf);
    }
}

TEST_CASE("radiance_with_refraction: F from Schlick or the exact formula, as asked", "[stage9]") {
    INFO(uses("radiance_with_refraction",
              "refracted_ray, the fresnel_ and media functions, stage 7"));
    INFO(
        "Into glass (1.5) at 60 degrees, Kt = 1, Ks = 0: I = F sky + (1 - F) floor, so I.x = F: "
        "Schlick's 0.04 + 0.96 / 32 = 0.07, the exact 0.0891867 (fresnel_exact's tests work it).");
    const double s = std::sqrt(3.0) / 2;
    const Ray eye{{-s, 0, 0.5}, {s, 0, -0.5}};
    const MediumShadeFunction top = [](const Ray& ray) -> std::optional<MediumHit> {
        return glass(ray, {0, 0, 1}, 1.5, true, Color(1.0), Color(0.0), Color(0.0));
    };
    for (const auto& [schlick, expected] : {std::pair{true, 0.07}, std::pair{false, 0.0891867}}) {
        CAPTURE(schlick);
        std::vector<Ray> asked;
        const Color got = radiance_with_refraction(glass_then_sky_and_floor(top, asked), eye, 1, {},
                                                   schlick, kAlongNormal);
        REQUIRE(got.x == Approx(expected).epsilon(1e-6));
        REQUIRE(got.y == Approx(2 * expected + (1 - expected)).epsilon(1e-6));
    }
}

TEST_CASE("radiance_with_refraction: total internal reflection sends everything back", "[stage9]") {
    INFO(uses("radiance_with_refraction",
              "refracted_ray, the fresnel_ and media functions, stage 7"));
    INFO(
        "Inside glass (1.5), going up at 60 degrees onto its top surface: beyond the critical "
        "angle, F = 1. Kt = 1, Ks = 0: the whole Kt goes to the reflected ray, down to the floor: "
        "I = (0, 1, 2), and no refracted ray is traced: 2 calls.");
    const double s = std::sqrt(3.0) / 2;
    const Ray up_inside{{-s, 0, -0.5}, {s, 0, 0.5}};
    const MediumShadeFunction top = [](const Ray& ray) -> std::optional<MediumHit> {
        return glass(ray, {0, 0, -1}, 1.5, false, Color(1.0), Color(0.0), Color(0.0));
    };
    for (bool schlick : {false, true}) {
        CAPTURE(schlick);
        std::vector<Ray> asked;
        const Color got = radiance_with_refraction(glass_then_sky_and_floor(top, asked), up_inside,
                                                   3, {Medium{7, 1.5}}, schlick, kAlongNormal);
        REQUIRE_THAT(got, IsNear(kFloor, 1e-15));
        REQUIRE(asked.size() == 2);
        REQUIRE(asked[1].direction.z < 0.0);
    }
}

TEST_CASE("radiance_with_refraction: in and out of a slab, the media go with the ray", "[stage9]") {
    INFO(uses("radiance_with_refraction",
              "refracted_ray, the fresnel_ and media functions, stage 7"));
    INFO(
        "A slab of index 3, maxdepth 2, head-on from above. At the top (air -> 3) F = 1/4: a "
        "quarter of the sky, three quarters through. At the bottom the ray is inside the slab "
        "and leaves it (3 -> air): F = 1/4 again, and three quarters of that reach the floor: "
        "I = sky / 4 + (9/16) floor = (0.25, 1.0625, 1.125). A refracted ray sent on in air "
        "instead would see no surface at the bottom (1 -> 1, F = 0): (0.25, 1.25, 1.5). 5 calls: "
        "eye, sky, bottom, top from inside (no bounce left), floor.");
    std::vector<Ray> asked;
    const Color got =
        radiance_with_refraction(glass_slab(asked), kDown, 2, {}, false, kAlongNormal);
    CHECK(got == Color(0.25, 1.0625, 1.125));
    CHECK(asked.size() == 5);
}

TEST_CASE("radiance_with_refraction: with no bounce left, neither ray is traced", "[stage9]") {
    INFO(uses("radiance_with_refraction",
              "refracted_ray, the fresnel_ and media functions, stage 7"));
    std::vector<Ray> asked;
    const MediumShadeFunction top = [](const Ray& ray) -> std::optional<MediumHit> {
        return glass(ray, {0, 0, 1}, 3, true, Color(1.0), Color(0.5), Color(0.25));
    };
    const Color got = radiance_with_refraction(glass_then_sky_and_floor(top, asked), kDown, 0, {},
                                               false, kAlongNormal);
    CHECK(got == Color(0.25));
    CHECK(asked.size() == 1);
}

TEST_CASE("radiance_with_refraction: a black weight traces no ray", "[stage9]") {
    INFO(uses("radiance_with_refraction",
              "refracted_ray, the fresnel_ and media functions, stage 7"));
    INFO(
        "An opaque, matte surface (Ks = Kt = 0) traces nothing: 1 call. A clear solid of index 1 "
        "head-on has F = 0, so with Ks = 0 the reflected weight Ks + Kt F is exactly black: only "
        "the refracted ray, 2 calls, and I is the floor.");
    for (bool schlick : {false, true}) {
        CAPTURE(schlick);
        std::vector<Ray> matte_asked;
        const MediumShadeFunction matte = [](const Ray& ray) -> std::optional<MediumHit> {
            return opaque(ray, Color(0.5));
        };
        const Color matte_got = radiance_with_refraction(
            glass_then_sky_and_floor(matte, matte_asked), kDown, 5, {}, schlick, kAlongNormal);
        REQUIRE(matte_got == Color(0.5));
        REQUIRE(matte_asked.size() == 1);

        std::vector<Ray> matched_asked;
        const MediumShadeFunction matched = [](const Ray& ray) -> std::optional<MediumHit> {
            return glass(ray, {0, 0, 1}, 1.0, true, Color(1.0), Color(0.0), Color(0.0));
        };
        const Color matched_got = radiance_with_refraction(
            glass_then_sky_and_floor(matched, matched_asked), kDown, 5, {}, schlick, kAlongNormal);
        REQUIRE(matched_got == kFloor);
        REQUIRE(matched_asked.size() == 2);
    }
}
