// Public tests for stage 11, the surface's derivatives and the tangent frame. Run them with
// `ctest --preset student -L stage11`, one function's with
// `build/student/bin/raystep_stage11_tests "tangent_frame:*"`.

#include <optional>

#include <glm/geometric.hpp>

#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/vec3_matchers.h"
#include "stages/11_surface_detail/surface_detail.h"

using namespace raystep;
using raystep::testing::IsNear;

TEST_CASE("surface_derivatives: u along one edge and v along the other", "[stage11]") {
    // u = 1 at p1, two units along x; v = 1 at p2, three units along y.
    const std::optional<SurfaceDerivatives> d =
        surface_derivatives({0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {0, 0}, {1, 0}, {0, 1});
    REQUIRE(d);
    CHECK_THAT(d->dpdu, IsNear(Vec3(2, 0, 0), 1e-15));
    CHECK_THAT(d->dpdv, IsNear(Vec3(0, 3, 0), 1e-15));
}

TEST_CASE("surface_derivatives: uvs swapped between the vertices swap the derivatives",
          "[stage11]") {
    const std::optional<SurfaceDerivatives> d =
        surface_derivatives({0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {0, 0}, {0, 1}, {1, 0});
    REQUIRE(d);
    CHECK_THAT(d->dpdu, IsNear(Vec3(0, 3, 0), 1e-15));
    CHECK_THAT(d->dpdv, IsNear(Vec3(2, 0, 0), 1e-15));
}

TEST_CASE("surface_derivatives: map the uv edges back onto the triangle's edges", "[stage11]") {
    // Any triangle and any uvs with area: e1 = du1 dp/du + dv1 dp/dv, and so for e2.
    const Vec3 p0{0.3, -1.2, 2.0}, p1{1.7, 0.4, 1.1}, p2{-0.5, 0.9, 3.3};
    const Vec2 uv0{0.1, 0.2}, uv1{0.8, 0.35}, uv2{0.3, 0.9};
    const std::optional<SurfaceDerivatives> d = surface_derivatives(p0, p1, p2, uv0, uv1, uv2);
    REQUIRE(d);
    const Vec2 d1 = uv1 - uv0, d2 = uv2 - uv0;
    CHECK_THAT(d1.x * d->dpdu + d1.y * d->dpdv, IsNear(p1 - p0, 1e-14));
    CHECK_THAT(d2.x * d->dpdu + d2.y * d->dpdv, IsNear(p2 - p0, 1e-14));
}

TEST_CASE("surface_derivatives: uvs on a line give nullopt", "[stage11]") {
    // All three uvs on the line v = u: the determinant is 0.
    CHECK_FALSE(surface_derivatives({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0}, {0.5, 0.5}, {1, 1}));
}

TEST_CASE("tangent_frame: orthonormal, with the tangent along dp/du's part across n", "[stage11]") {
    // dp/du leans out of the surface: Gram-Schmidt keeps only its part in the plane.
    const Vec3 n{0, 0, 1};
    const std::optional<TangentFrame> frame = tangent_frame({{2, 0, 1}, {0, 3, -1}}, n);
    REQUIRE(frame);
    CHECK_THAT(frame->tangent, IsNear(Vec3(1, 0, 0), 1e-15));
    CHECK_THAT(frame->bitangent, IsNear(Vec3(0, 1, 0), 1e-15));
    CHECK_THAT(frame->normal, IsNear(n, 1e-15));
}

TEST_CASE("tangent_frame: a mirrored texture turns the bitangent to dp/dv's side", "[stage11]") {
    // v runs along -y: n x t = +y points away from dp/dv, so the bitangent is -y.
    const std::optional<TangentFrame> frame = tangent_frame({{1, 0, 0}, {0, -1, 0}}, {0, 0, 1});
    REQUIRE(frame);
    CHECK_THAT(frame->bitangent, IsNear(Vec3(0, -1, 0), 1e-15));
}

TEST_CASE("tangent_frame: any dp/du off the normal gives an orthonormal frame", "[stage11]") {
    const Vec3 n = glm::normalize(Vec3(0.3, -0.5, 0.8));
    const std::optional<TangentFrame> frame = tangent_frame({{0.7, 0.2, 0.1}, {-0.1, 0.9, 0.4}}, n);
    REQUIRE(frame);
    CHECK_THAT(glm::length(frame->tangent), IsNear(1.0, 1e-15));
    CHECK_THAT(glm::length(frame->bitangent), IsNear(1.0, 1e-15));
    CHECK_THAT(glm::dot(frame->tangent, n), IsNear(0.0, 1e-15));
    CHECK_THAT(glm::dot(frame->bitangent, n), IsNear(0.0, 1e-15));
    CHECK_THAT(glm::dot(frame->tangent, frame->bitangent), IsNear(0.0, 1e-15));
}

TEST_CASE("tangent_frame: dp/du along the normal gives nullopt", "[stage11]") {
    CHECK_FALSE(tangent_frame({{0, 0, 2}, {0, 1, 0}}, {0, 0, 1}));
}
