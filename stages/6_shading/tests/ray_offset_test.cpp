// Public tests for stage 6, rays that leave a surface: spawn_ray under each offset rule and
// shadow_ray. Run them with `ctest --preset student -L stage6`.
//
// Each test calls your function before its CHECKs, so a stub is reported once. The rules fix the
// origin and the t range exactly, so most checks here are ==. A loop over cases stops at the first
// that fails.

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "base/testing/number_text.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/6_shading/shading.h"

using namespace raystep;
using raystep::testing::exact_text;
using raystep::testing::IsNear;
using raystep::testing::uses;

namespace {

const double kInf = std::numeric_limits<double>::infinity();

// A point on the plane z = 3, normal +z, seen from above, whose coordinates may be off the exact
// hit point by up to (1e-12, 2e-12, 3e-12).
SurfacePoint on_plane_z3() {
    return {{1, 2, 3}, {1e-12, 2e-12, 3e-12}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
}

const Vec3 kUp{0, 0.6, 0.8};     // leaves on the normal's side
const Vec3 kDown{0, 0.6, -0.8};  // leaves by the back

RayOffset rule(OffsetRule r, double epsilon) {
    return {r, epsilon};
}

}  // namespace

TEST_CASE("spawn_ray: along_ray starts at the point and counts hits from t = epsilon", "[stage6]") {
    INFO(uses("spawn_ray", "stage 1's dot"));
    const Ray up = spawn_ray(on_plane_z3(), kUp, 7.0, rule(OffsetRule::along_ray, 0.25));
    const Ray down = spawn_ray(on_plane_z3(), kDown, 7.0, rule(OffsetRule::along_ray, 0.25));
    for (const Ray& ray : {up, down}) {
        REQUIRE(ray.origin == Vec3(1, 2, 3));
        REQUIRE(ray.t_min == 0.25);
        REQUIRE(ray.t_max == 7.0);
    }
    CHECK_THAT(up.direction, IsNear(kUp, 1e-15));
    CHECK_THAT(down.direction, IsNear(kDown, 1e-15));
}

TEST_CASE("spawn_ray: along_normal starts epsilon along the normal, t from 0", "[stage6]") {
    INFO(uses("spawn_ray", "stage 1's dot"));
    INFO("(1, 2, 3) + 0.25 (0, 0, 1) = (1, 2, 3.25).");
    const Ray ray = spawn_ray(on_plane_z3(), kUp, 7.0, rule(OffsetRule::along_normal, 0.25));
    CHECK(ray.origin == Vec3(1, 2, 3.25));
    CHECK(ray.t_min == 0.0);
    CHECK(ray.t_max == 7.0);
    CHECK_THAT(ray.direction, IsNear(kUp, 1e-15));
}

TEST_CASE("spawn_ray: along_normal offsets to the back when the ray leaves by the back",
          "[stage6]") {
    INFO(uses("spawn_ray", "stage 1's dot"));
    INFO(
        "n . direction = -0.8 < 0: the ray goes through the surface (a light behind it, refraction "
        "later), so the origin moves to that side: (1, 2, 3) - 0.25 (0, 0, 1) = (1, 2, 2.75).");
    const Ray ray = spawn_ray(on_plane_z3(), kDown, 7.0, rule(OffsetRule::along_normal, 0.25));
    CHECK(ray.origin == Vec3(1, 2, 2.75));
    CHECK(ray.t_min == 0.0);
    CHECK(ray.t_max == 7.0);
}

TEST_CASE("spawn_ray: along_normal with a ray in the tangent plane uses the normal as given",
          "[stage6]") {
    INFO(uses("spawn_ray", "stage 1's dot"));
    INFO("n . direction = 0: neither side is the leaving one; the normal as the renderer gave it.");
    const Ray ray = spawn_ray(on_plane_z3(), {1, 0, 0}, 7.0, rule(OffsetRule::along_normal, 0.25));
    CHECK(ray.origin == Vec3(1, 2, 3.25));
}

TEST_CASE("spawn_ray: error_bound starts one ulp beyond the error along the normal", "[stage6]") {
    INFO(uses("spawn_ray", "stage 1's dot"));
    INFO(
        "d = |0| 1e-12 + |0| 2e-12 + |1| 3e-12 = 3e-12. Only z moves: 3 + 3e-12, then one ulp up. "
        "epsilon is set to 0.5 to show that error_bound ignores it.");
    const Ray ray = spawn_ray(on_plane_z3(), kUp, 7.0, rule(OffsetRule::error_bound, 0.5));
    CHECK(ray.origin == Vec3(1, 2, std::nextafter(3.0 + 3e-12, kInf)));
    CHECK(ray.t_min == 0.0);
    CHECK(ray.t_max == 7.0);
    CHECK_THAT(ray.direction, IsNear(kUp, 1e-15));
}

TEST_CASE("spawn_ray: error_bound leaving by the back offsets down, and the ulp goes down too",
          "[stage6]") {
    INFO(uses("spawn_ray", "stage 1's dot"));
    INFO("The normal flipped to (0, 0, -1): 3 - 3e-12, then one ulp towards -infinity.");
    const Ray ray = spawn_ray(on_plane_z3(), kDown, 7.0, rule(OffsetRule::error_bound, 0.5));
    CHECK(ray.origin == Vec3(1, 2, std::nextafter(3.0 - 3e-12, -kInf)));
    CHECK(ray.t_min == 0.0);
    CHECK(ray.t_max == 7.0);
}

TEST_CASE("spawn_ray: error_bound starts strictly beyond the error box, moves ~1 ulp sideways",
          "[stage6]") {
    INFO(uses("spawn_ray", "stage 1's dot"));
    INFO(
        "The exact hit point can be anywhere in the box position +- error, and over that box n . "
        "(p - position) reaches at most d = sum |n_i| error_i, n the normal on the side the ray "
        "leaves to. The origin must be strictly beyond: n . (origin - position) > d. Along n it "
        "goes no farther than d plus a few ulps of the point (no light leaks through thin walls), "
        "and sideways (perpendicular to n) it moves only by rounding, a few ulps. Errors here are "
        "1 to 64 units of 2^-52 of the point's size, as a renderer's are.");
    for (int k = 0; k < 1000; ++k) {
        PortableRandom random(6, k);  // case k, the same on every platform
        const double scale = std::pow(10.0, static_cast<double>(random.integer(-3, 6)));
        SurfacePoint point;
        point.position = random.point(100 * scale);
        const double size = std::max(
            {std::abs(point.position.x), std::abs(point.position.y), std::abs(point.position.z)});
        const double ulp_of_size = std::ldexp(size, -52);
        const double x = random.uniform(1, 64);
        const double y = random.uniform(1, 64);
        point.error = ulp_of_size * Vec3{x, y, random.uniform(1, 64)};
        point.normal = random.unit_vector();
        point.shading_normal = point.normal;
        point.to_eye = point.normal;
        const Vec3 direction = random.unit_vector();
        CAPTURE(k, point.position, point.error, point.normal, direction);

        const Ray ray = spawn_ray(point, direction, 5.0, rule(OffsetRule::error_bound, 0.0));

        // These differences and dot products round by about 1e-16 of d, far below the ulp the
        // rule adds.
        const Vec3 n = glm::dot(point.normal, direction) < 0.0 ? -point.normal : point.normal;
        const double d = glm::dot(glm::abs(n), point.error);
        const Vec3 moved = ray.origin - point.position;
        const double along = glm::dot(moved, n);
        const double sideways = glm::length(moved - along * n);
        // Catch prints these in fixed notation, 1e-15 as 0.0: here they are in full
        INFO("along n " << exact_text(along) << ", above d = " << exact_text(d)
                        << " and at most d + 4 ulps; sideways " << exact_text(sideways)
                        << ", at most 4 ulps = " << exact_text(4 * ulp_of_size));
        REQUIRE(along > d);
        REQUIRE(along <= d + 4 * ulp_of_size);
        REQUIRE(sideways <= 4 * ulp_of_size);
        REQUIRE(ray.t_min == 0.0);
        REQUIRE(ray.t_max == 5.0);
    }
}

TEST_CASE("spawn_ray: the error_bound offset scales with the error (x1000 error, x1000 offset)",
          "[stage6]") {
    INFO(uses("spawn_ray", "stage 1's dot"));
    INFO(
        "This is what \"no tuning\" means: a scene 1000 times larger (or farther out) has points "
        "1000 times less precise, and the offset follows. n = (0, 0.6, 0.8), error 1e-12 and 1e-9 "
        "per coordinate: d = (0.6 + 0.8) 1e-12 = 1.4e-12, and 1.4e-9. along_normal's epsilon stays "
        "where it is, however large the error.");
    SurfacePoint precise = on_plane_z3();
    precise.normal = {0, 0.6, 0.8};
    precise.error = Vec3(1e-12);
    SurfacePoint coarse = precise;
    coarse.error = Vec3(1e-9);
    const RayOffset error_bound = rule(OffsetRule::error_bound, 0.0);
    const RayOffset along_normal = rule(OffsetRule::along_normal, 0.25);

    const Ray from_precise = spawn_ray(precise, kUp, 7.0, error_bound);
    const Ray from_coarse = spawn_ray(coarse, kUp, 7.0, error_bound);
    const Ray fixed_precise = spawn_ray(precise, kUp, 7.0, along_normal);
    const Ray fixed_coarse = spawn_ray(coarse, kUp, 7.0, along_normal);

    const double offset_precise = glm::dot(from_precise.origin - precise.position, precise.normal);
    const double offset_coarse = glm::dot(from_coarse.origin - coarse.position, coarse.normal);
    // In units of 1e-12 and 1e-9, so that a failure prints 1.4 rather than 0.0
    REQUIRE(offset_precise * 1e12 == Approx(1.4).epsilon(1e-2));  // + an ulp of 3 (4.4e-16) or so
    REQUIRE(offset_coarse * 1e9 == Approx(1.4).epsilon(1e-5));
    REQUIRE(offset_coarse / offset_precise == Approx(1000).epsilon(1e-2));
    REQUIRE(fixed_precise.origin == fixed_coarse.origin);
}

TEST_CASE("spawn_ray: error_bound leaves even a point with no rounding error", "[stage6]") {
    INFO(uses("spawn_ray", "stage 1's dot"));
    INFO(
        "The point (1, 0, 3) exactly on the plane y = 0, error 0: d = 0, so the offset is 0, but "
        "the origin must still leave the plane (t_min is 0, and a ray starting on the plane hits "
        "it at t = 0). The ulp step along the normal's sign takes y from 0 to the smallest double "
        "above.");
    const SurfacePoint point{{1, 0, 3}, {0, 0, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    const Ray ray = spawn_ray(point, {0.6, 0.8, 0}, 7.0, rule(OffsetRule::error_bound, 0.0));
    CHECK(ray.origin.x == 1.0);
    CHECK(ray.origin.y > 0.0);
    CHECK(ray.origin.z == 3.0);
}

TEST_CASE("shadow_ray: towards a point light, over exactly the light's distance", "[stage6]") {
    INFO(uses("shadow_ray", "spawn_ray"));
    INFO(
        "The light 5 away along (0, 0.6, 0.8): the ray ends at the light, so that an object beyond "
        "the light casts no shadow.");
    const LightSample light{kUp, 5.0, Color(1.0)};
    const Ray along_ray = shadow_ray(on_plane_z3(), light, rule(OffsetRule::along_ray, 0.25));
    CHECK(along_ray.origin == Vec3(1, 2, 3));
    CHECK(along_ray.t_min == 0.25);
    CHECK(along_ray.t_max == 5.0);
    CHECK_THAT(along_ray.direction, IsNear(kUp, 1e-15));

    const Ray error_bound = shadow_ray(on_plane_z3(), light, rule(OffsetRule::error_bound, 0.0));
    CHECK(error_bound.origin == Vec3(1, 2, std::nextafter(3.0 + 3e-12, kInf)));
    CHECK(error_bound.t_min == 0.0);
    CHECK(error_bound.t_max == 5.0);
}

TEST_CASE("shadow_ray: towards a directional light, t_max is infinite", "[stage6]") {
    INFO(uses("shadow_ray", "spawn_ray"));
    const LightSample sun{kUp, kInf, Color(1.0)};
    for (const OffsetRule r :
         {OffsetRule::along_ray, OffsetRule::along_normal, OffsetRule::error_bound}) {
        CAPTURE(static_cast<int>(r));
        const Ray ray = shadow_ray(on_plane_z3(), sun, rule(r, 0.25));
        REQUIRE(ray.t_max == kInf);
    }
}

TEST_CASE("shadow_ray: towards a light behind the surface, starts on the back side", "[stage6]") {
    INFO(uses("shadow_ray", "spawn_ray"));
    INFO(
        "A light below the plane z = 3 (N . L < 0): shading gives it no term anyway, but the "
        "shadow ray must still start on the side it leaves to, like any ray through the surface.");
    const LightSample below{kDown, 5.0, Color(1.0)};
    const Ray along_normal = shadow_ray(on_plane_z3(), below, rule(OffsetRule::along_normal, 0.25));
    const Ray error_bound = shadow_ray(on_plane_z3(), below, rule(OffsetRule::error_bound, 0.0));
    CHECK(along_normal.origin == Vec3(1, 2, 2.75));
    INFO("error_bound's origin z = " << exact_text(error_bound.origin.z)
                                     << ", which must be below 3 - 3e-12 = "
                                     << exact_text(3.0 - 3e-12));
    CHECK(error_bound.origin.z < 3.0 - 3e-12);
}
