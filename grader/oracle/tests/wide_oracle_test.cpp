// Tests of the long-double oracles of stages 2 and 5 to 7 (grading/2_rays/camera_oracle.h,
// transform_oracle.h, shading_oracle.h, recursion_oracle.h) on answers worked out by hand, the same
// ones the public cases of the stages' checks (grading/) state in their comments.

#include <cmath>

#include "base/testing/catch.h"
#include "base/testing/special_values.h"
#include "grader/oracle/tests/wide_near.h"
#include "grading/2_rays/camera_oracle.h"
#include "grading/5_transforms/transform_oracle.h"
#include "grading/6_shading/shading_oracle.h"
#include "grading/7_recursion/recursion_oracle.h"

using namespace raystep;

namespace {

using raystep::testing::kInf;
using raystep::testing::wide_near;

}  // namespace

TEST_CASE("expected_perspective: pixel (1, 2) of 4 x 4 at fovy 90 looks along (-0.25, -0.25, -1)",
          "[grader]") {
    CameraCase c{{0, 0, 0}, {0, 0, -3}, {0, 1, 0}, 4, 4};
    c.fovy = 90;
    const ExpectedCameraRay ray = expected_perspective(c, 1, 2);
    const Vec3 through{-0.25, -0.25, -1};
    CHECK(wide_near(widen(ray.direction), through / std::sqrt(1.125)));
    CHECK(ray.origin == Vec3(0, 0, 0));
    CHECK(ray.direction_tolerance > 0);
    CHECK(ray.direction_tolerance < 1e-14);
}

TEST_CASE(
    "expected_orthographic: pixel (0, 0) of a 4 x 2 window [-2, 2] x [-1, 1] starts at "
    "(-1.5, 0.5, 5)",
    "[grader]") {
    CameraCase c{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 4, 2, true};
    c.left = -2;
    c.right = 2;
    c.bottom = -1;
    c.top = 1;
    const ExpectedCameraRay ray = expected_orthographic(c, 0, 0);
    CHECK(wide_near(widen(ray.origin), {-1.5, 0.5, 5}));
    CHECK(wide_near(widen(ray.direction), {0, 0, -1}));
}

TEST_CASE("wide_rotation: a quarter turn about +z takes x to y", "[grader]") {
    const WideMat m = wide_rotation({0, 0, 1}, 90);
    CHECK(wide_near(WideVec(m[0]), {0, 1, 0}));
    CHECK(wide_near(WideVec(m[1]), {-1, 0, 0}));
    CHECK(wide_near(WideVec(m[2]), {0, 0, 1}));
}

TEST_CASE("wide_compose: T R S moves (1, 0, 0) to (1, 4, 3) and back", "[grader]") {
    const std::vector<TransformOp> ops{{TransformOp::Kind::translate, {1, 2, 3}, 0.0},
                                       {TransformOp::Kind::rotate, {0, 0, 1}, 90.0},
                                       {TransformOp::Kind::scale, {2, 1, 1}, 0.0}};
    const Transform t = transform_of(ops);
    const WideProduct moved = wide_product(t.matrix, {1, 0, 0}, 1.0);
    CHECK(wide_near(moved.value, {1, 4, 3}));
    const WideProduct back = wide_product(t.inverse, {1, 4, 3}, 1.0);
    CHECK(wide_near(back.value, {1, 0, 0}));
    // Three ops: every entry's tolerance is 8 (3 + 1) ulps of its size, never zero where the
    // entry is not.
    const WideTransform w = wide_compose(ops);
    CHECK(w.matrix_tolerance[3][0] > 0);
    CHECK(w.matrix_tolerance[3][0] < 1e-13L);
}

TEST_CASE("wide_normal: S(2, 1, 4) takes the normal (1, 1, 1) to (0.5, 1, 0.25) normalized",
          "[grader]") {
    const Transform t = transform_of({{TransformOp::Kind::scale, {2, 1, 4}, 0.0}});
    const WideNormal n = wide_normal(t.inverse, WideVec(1, 1, 1));
    const double length = std::sqrt(0.25 + 1 + 0.0625);
    CHECK(wide_near(n.value, Vec3(0.5, 1, 0.25) / length));
}

TEST_CASE("wide_transformed_hit: down the y axis onto the ellipsoid of radii (3, 2, 1) at t = 8",
          "[grader]") {
    const Transform t = transform_of({{TransformOp::Kind::translate, {1, 0, 0}, 0.0},
                                      {TransformOp::Kind::scale, {3, 2, 1}, 0.0}});
    const TransformedSphereHit hit =
        wide_transformed_hit({{1, 10, 0}, {0, -1, 0}}, {{0, 0, 0}, 1.0}, t);
    REQUIRE(hit.hit);
    CHECK(std::abs(hit.t - 8) <= 1e-14);
    CHECK(wide_near(hit.normal.value, {0, 1, 0}));
    // Above its top (z = 1): a miss.
    CHECK_FALSE(wide_transformed_hit({{1, 10, 1.5}, {0, -1, 0}}, {{0, 0, 0}, 1.0}, t).hit);
}

TEST_CASE("wide_point_light: 5 away with attenuation 3, the colour over 3", "[grader]") {
    const WideLightSample s =
        wide_point_light({{2, 5, -1}, {3, 1.5, 0.75}, {1, 0.2, 0.04}}, {-1, 1, -1});
    CHECK(wide_near(s.direction, {0.6, 0.8, 0}));
    CHECK(std::abs(s.distance - 5) <= 1e-15L);
    CHECK(wide_near(s.intensity, {1, 0.5, 0.25}));
    CHECK(std::isinf(wide_directional_light({{0, -6, 8}, {0.3, 0.6, 0.9}}).distance));
}

TEST_CASE("wide_blinn_phong: the highlight from above is Ks (N . H)^4 = 0.64 Ks", "[grader]") {
    Material m;
    m.specular = {1, 0.5, 0.25};
    m.shininess = 4;
    const SurfacePoint up{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    const WideColor c = wide_blinn_phong(m, up, {{0.8, 0.6, 0}, 10.0, Color(1.0)});
    CHECK(wide_near(c.value, {0.64, 0.32, 0.16}));
    // A light below the floor: black, with no tolerance.
    const WideColor below = wide_blinn_phong(m, up, {{0.6, -0.8, 0}, 10.0, Color(1.0)});
    CHECK(wide_near(below.value, {0, 0, 0}, 0));
    CHECK(wide_near(below.tolerance, {0, 0, 0}, 0));
}

TEST_CASE("expected_radiance: a black mirror ends the chain after its local colour", "[grader]") {
    const SurfacePoint floor{
        {1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {0, 1, 0}, {-std::sqrt(0.5), std::sqrt(0.5), 0}};
    const Ray eye{{0, 1, 0}, {1, -1, 0}, 0.0, kInf};
    const RayOffset along_ray{OffsetRule::along_ray, 1e-4};
    const Script script{ShadedHit{floor, Color(0.3), Color(0.5)},
                        ShadedHit{floor, Color(1.0), Color(0.0)},
                        ShadedHit{floor, Color(7.0), Color(1.0)}};
    const ExpectedRadiance e = expected_radiance(script, eye, 5, along_ray);
    // 0.3 + 0.5 * 1: the third hit is never asked about.
    CHECK(wide_near(e.colour, Vec3(0.8)));
    CHECK(e.rays.size() == 2);
    // The mirror ray leaves the floor at 45 degrees, from the point itself under along_ray.
    CHECK(wide_near(e.rays[1].direction, {std::sqrt(0.5), std::sqrt(0.5), 0}));
    CHECK(e.rays[1].t_min == 1e-4);
    CHECK(e.rays[1].t_max == kInf);
}
