// Public tests for stage 11, values interpolated over a triangle and a sphere's texture
// coordinates. Run them with `ctest --preset student -L stage11`, one function's with
// `build/student/bin/raystep_stage11_tests "interpolate_normal:*"`.

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/vec3_matchers.h"
#include "stages/11_surface_detail/surface_detail.h"

using namespace raystep;
using raystep::testing::IsNear;

namespace {

constexpr double kPi = glm::pi<double>();

}  // namespace

TEST_CASE("interpolate_normal: at a vertex, that vertex's normal", "[stage11]") {
    const Vec3 n0{0, 0, 1}, n1{1, 0, 0}, n2{0, 1, 0};
    CHECK_THAT(interpolate_normal(n0, n1, n2, 0.0, 0.0), IsNear(n0, 1e-15));
    CHECK_THAT(interpolate_normal(n0, n1, n2, 1.0, 0.0), IsNear(n1, 1e-15));
    CHECK_THAT(interpolate_normal(n0, n1, n2, 0.0, 1.0), IsNear(n2, 1e-15));
}

TEST_CASE("interpolate_normal: weighs n0 by 1 - beta - gamma and normalizes the sum", "[stage11]") {
    // At the centroid the three axes sum to (1, 1, 1) / 3, of length 1 / sqrt(3): normalized,
    // (1, 1, 1) / sqrt(3).
    const Vec3 centroid = interpolate_normal({1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.0 / 3, 1.0 / 3);
    CHECK_THAT(centroid, IsNear(Vec3(1.0) / std::sqrt(3.0), 1e-15));
    // Beta weighs n1 and gamma n2, not the other way round: (0.2 n0 + 0.5 n1 + 0.3 n2).
    const Vec3 n = interpolate_normal({1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.5, 0.3);
    CHECK_THAT(n, IsNear(glm::normalize(Vec3(0.2, 0.5, 0.3)), 1e-15));
}

TEST_CASE("interpolate_normal: vertex normals of any length give a unit normal", "[stage11]") {
    // OBJ files need not hold unit normals: (0, 0, 3) and (0, 0, 0.5) both say +z.
    CHECK_THAT(interpolate_normal({0, 0, 3}, {0, 0, 0.5}, {0, 0, 7}, 0.25, 0.25),
               IsNear(Vec3(0, 0, 1), 1e-15));
    // And a longer one weighs more: the sum as written, normalized once, (2, 1, 1) / sqrt(6) at
    // the centroid, not the mean of the three made unit first.
    CHECK_THAT(interpolate_normal({2, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.0 / 3, 1.0 / 3),
               IsNear(Vec3(2, 1, 1) / std::sqrt(6.0), 1e-15));
}

TEST_CASE("interpolate_normal: opposing normals that cancel throw domain_error", "[stage11]") {
    // Halfway between +z and -z the sum is zero: no direction to normalize.
    CHECK_THROWS_AS(interpolate_normal({0, 0, 1}, {0, 0, -1}, {1, 0, 0}, 0.5, 0.0),
                    std::domain_error);
}

TEST_CASE("interpolate_uv: at the vertices and between them", "[stage11]") {
    const Vec2 uv0{0.0, 0.0}, uv1{1.0, 0.0}, uv2{0.25, 1.0};
    const Vec2 at1 = interpolate_uv(uv0, uv1, uv2, 1.0, 0.0);
    CHECK_THAT(at1.x, IsNear(1.0, 1e-15));
    CHECK_THAT(at1.y, IsNear(0.0, 1e-15));
    // 0.2 uv0 + 0.5 uv1 + 0.3 uv2 = (0.5 + 0.075, 0.3).
    const Vec2 inside = interpolate_uv(uv0, uv1, uv2, 0.5, 0.3);
    CHECK_THAT(inside.x, IsNear(0.575, 1e-15));
    CHECK_THAT(inside.y, IsNear(0.3, 1e-15));
}

TEST_CASE("sphere_uv: the poles, the front and the sides", "[stage11]") {
    // v is 1 at the north pole (+y) and 0 at the south; u is 0.5 facing +z, 0.75 facing +x and
    // 0.25 facing -x.
    CHECK_THAT(sphere_uv({0, 1, 0}).y, IsNear(1.0, 1e-15));
    CHECK_THAT(sphere_uv({0, -1, 0}).y, IsNear(0.0, 1e-15));
    const Vec2 front = sphere_uv({0, 0, 1});
    CHECK_THAT(front.x, IsNear(0.5, 1e-15));
    CHECK_THAT(front.y, IsNear(0.5, 1e-15));
    CHECK_THAT(sphere_uv({1, 0, 0}).x, IsNear(0.75, 1e-15));
    CHECK_THAT(sphere_uv({-1, 0, 0}).x, IsNear(0.25, 1e-15));
    // 45 degrees above the equator, facing +z: theta = pi / 4, so v = 0.75.
    CHECK_THAT(sphere_uv(glm::normalize(Vec3(0, 1, 1))).y, IsNear(0.75, 1e-15));
}

TEST_CASE("sphere_uv: u stays in [0, 1] all the way round", "[stage11]") {
    for (int k = 0; k < 64; ++k) {
        const double phi = 2.0 * kPi * k / 64.0;
        const Vec2 uv = sphere_uv({std::sin(phi), 0.0, std::cos(phi)});
        CAPTURE(k, uv.x);
        CHECK(uv.x >= 0.0);
        CHECK(uv.x <= 1.0);
    }
}

TEST_CASE("sphere_uv: keeps its digits near the poles", "[stage11]") {
    // 1e-9 radians from the north pole n.y rounds to exactly 1, and acos(1) = 0 loses the angle
    // altogether; atan2 of the horizontal part keeps it: v = 1 - 1e-9 / pi.
    const double angle = 1e-9;
    const Vec2 uv = sphere_uv({0.0, std::cos(angle), std::sin(angle)});
    CHECK_THAT((1.0 - uv.y) * kPi / angle, IsNear(1.0, 1e-6));
}
