// Public tests for stage 2, cameras. Run them with `ctest --preset student -L stage2`, one
// function's with `build/student/bin/raystep_stage2_tests "perspective_ray:*"`.
//
// The ray tests build their cameras by hand, so perspective_ray and orthographic_ray can be tested
// before make_perspective_camera and make_orthographic_camera work. Each test calls your function
// before its CHECKs: a stub ends the test case at its first call and is reported once. The random
// loops REQUIRE, so a bug is reported at the first case that shows it. The cameras are built with
// your stage-1 functions: where stage 1's tests fail, fix those first.

#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "base/testing/number_text.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/2_rays/camera.h"

using namespace raystep;
using raystep::testing::exact_text;
using raystep::testing::IsNear;
using raystep::testing::uses;

namespace {

// The camera make_perspective_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, fovy, width, height) gives,
// built by hand: at +5 z looking at the origin, +y up, so u = +x, v = +y, w = +z.
PerspectiveCamera front_camera(double fovy, int width, int height) {
    const double half_height = std::tan(glm::radians(fovy) / 2);
    return {{0, 0, 5},
            {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
            half_height * width / height,
            half_height,
            width,
            height};
}

// The camera make_perspective_camera(from, at, up, ...) gives, built by hand.
PerspectiveCamera camera_looking(const Vec3& from, const Vec3& at, const Vec3& up, double fovy,
                                 int width, int height) {
    const Vec3 w = glm::normalize(from - at);
    const Vec3 u = glm::normalize(glm::cross(up, w));
    const double half_height = std::tan(glm::radians(fovy) / 2);
    return {from,  {u, glm::cross(w, u), w}, half_height * width / height, half_height, width,
            height};
}

std::string text(const PerspectiveCamera& c) {
    return "camera: eye " + exact_text(c.eye) + ", u " + exact_text(c.frame.u) + ", v " +
           exact_text(c.frame.v) + ", w " + exact_text(c.frame.w) + ", half_width " +
           exact_text(c.half_width) + ", half_height " + exact_text(c.half_height) + ", " +
           std::to_string(c.width) + " x " + std::to_string(c.height) + " pixels";
}

std::string text(const OrthographicCamera& c) {
    return "camera: eye " + exact_text(c.eye) + ", u " + exact_text(c.frame.u) + ", v " +
           exact_text(c.frame.v) + ", w " + exact_text(c.frame.w) + ", window [" +
           exact_text(c.left) + ", " + exact_text(c.right) + "] x [" + exact_text(c.bottom) + ", " +
           exact_text(c.top) + "], " + std::to_string(c.width) + " x " + std::to_string(c.height) +
           " pixels";
}

// The orthographic camera at +5 z looking at the origin, +y up, over the given window.
OrthographicCamera front_window(double left, double right, double bottom, double top, int width,
                                int height) {
    return {{0, 0, 5}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, left, right, bottom, top, width, height};
}

// What make_perspective_camera is given: the scene file's camera line and the image size.
struct CameraInput {
    Vec3 from, at, up;
    double fovy;
    int width, height;
};

// A camera anywhere in a 20-wide cube, looking anywhere, with any fovy from 5 to 150 degrees and
// an image of 1 to 300 pixels a side.
CameraInput random_camera_input(PortableRandom& random) {
    CameraInput input;
    input.from = random.point(10.0);
    input.at = random.point(10.0);
    input.up = random.point(10.0);
    input.fovy = random.uniform(5.0, 150.0);
    input.width = static_cast<int>(random.integer(1, 300));
    input.height = static_cast<int>(random.integer(1, 300));
    return input;
}

bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

TEST_CASE("make_perspective_camera: frame, eye and half extents", "[stage2]") {
    INFO(uses("make_perspective_camera", "stage 1's orthonormal_frame"));
    INFO(
        "make_perspective_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90, 200, 100): tan(45 degrees) "
        "= 1, and the image is twice as wide as tall");
    const PerspectiveCamera c =
        make_perspective_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90.0, 200, 100);
    CHECK(c.eye == Vec3(0, 0, 5));
    CHECK_THAT(c.frame.u, IsNear(Vec3{1, 0, 0}, 1e-15));
    CHECK_THAT(c.frame.v, IsNear(Vec3{0, 1, 0}, 1e-15));
    CHECK_THAT(c.frame.w, IsNear(Vec3{0, 0, 1}, 1e-15));
    CHECK(c.half_height == Approx(1.0));
    CHECK(c.half_width == Approx(2.0));
    CHECK(c.width == 200);
    CHECK(c.height == 100);
}

TEST_CASE("make_perspective_camera: agrees with the camera built by hand on random input",
          "[stage2]") {
    INFO(uses("make_perspective_camera", "stage 1's orthonormal_frame"));
    for (int k = 0; k < 300; ++k) {
        PortableRandom random(22, static_cast<std::uint64_t>(k));  // case k, on every platform
        const auto [from, at, up, fovy, width, height] = random_camera_input(random);
        CAPTURE(k, from, at, up, fovy, width, height);
        const PerspectiveCamera c = make_perspective_camera(from, at, up, fovy, width, height);
        const PerspectiveCamera expected = camera_looking(from, at, up, fovy, width, height);
        REQUIRE_THAT(c.eye, IsNear(expected.eye, 1e-15));
        REQUIRE_THAT(c.frame.u, IsNear(expected.frame.u, 1e-9));
        REQUIRE_THAT(c.frame.v, IsNear(expected.frame.v, 1e-9));
        REQUIRE_THAT(c.frame.w, IsNear(expected.frame.w, 1e-9));
        REQUIRE(c.half_width == Approx(expected.half_width).epsilon(1e-12));
        REQUIRE(c.half_height == Approx(expected.half_height).epsilon(1e-12));
        REQUIRE(c.width == width);
        REQUIRE(c.height == height);
    }
}

TEST_CASE("perspective_ray: starts at the eye with a unit direction", "[stage2]") {
    INFO(uses("perspective_ray", "stage 1's normalize"));
    const PerspectiveCamera c = front_camera(60.0, 64, 48);
    INFO(text(c));
    const Ray ray = perspective_ray(c, 10, 20);
    CHECK(ray.origin == Vec3(0, 0, 5));
    CHECK(glm::length(ray.direction) == Approx(1.0).epsilon(1e-15));
    CHECK(ray.t_min == 0.0);
    CHECK(std::isinf(ray.t_max));
}

TEST_CASE("perspective_ray: the centre pixel of an odd-sized image looks at lookat", "[stage2]") {
    INFO(uses("perspective_ray", "stage 1's normalize"));
    const PerspectiveCamera c = front_camera(45.0, 101, 51);
    INFO(text(c));
    const Ray centre = perspective_ray(c, 50, 25);
    CHECK_THAT(centre.direction, IsNear(Vec3{0, 0, -1}, 1e-15));
}

TEST_CASE("perspective_ray: goes through pixel centres, not corners", "[stage2]") {
    INFO(uses("perspective_ray", "stage 1's normalize"));
    INFO(
        "2 x 2 pixels, fovy 90: the image plane at distance 1 spans [-1, 1] x [-1, 1], and pixel "
        "(0, 0) covers its top-left quarter, whose centre is (-0.5, 0.5).");
    const PerspectiveCamera c = front_camera(90.0, 2, 2);
    INFO(text(c));
    const Ray top_left = perspective_ray(c, 0, 0);
    const Ray bottom_right = perspective_ray(c, 1, 1);
    CHECK_THAT(top_left.direction, IsNear(glm::normalize(Vec3(-0.5, 0.5, -1)), 1e-15));
    CHECK_THAT(bottom_right.direction, IsNear(glm::normalize(Vec3(0.5, -0.5, -1)), 1e-15));
}

TEST_CASE("perspective_ray: row 0 is the top of the image, column 0 the left", "[stage2]") {
    INFO(uses("perspective_ray", "stage 1's normalize"));
    const PerspectiveCamera c = front_camera(45.0, 40, 30);
    INFO(text(c));
    const Vec3 top_left = perspective_ray(c, 0, 0).direction;
    const Vec3 bottom_right = perspective_ray(c, 39, 29).direction;
    CHECK(top_left.y > 0.0);  // up is +y
    CHECK(top_left.x < 0.0);  // right is +x
    CHECK(bottom_right.y < 0.0);
    CHECK(bottom_right.x > 0.0);
}

TEST_CASE("perspective_ray: a non-square image widens the horizontal field of view", "[stage2]") {
    INFO(uses("perspective_ray", "stage 1's normalize"));
    INFO("4 x 2 pixels, fovy 90: half_width = 2. Pixel column 0's centre is at x = -1.5.");
    const PerspectiveCamera c = front_camera(90.0, 4, 2);
    INFO(text(c));
    const Ray top_left = perspective_ray(c, 0, 0);
    const Ray bottom_right = perspective_ray(c, 3, 1);
    CHECK_THAT(top_left.direction, IsNear(glm::normalize(Vec3(-1.5, 0.5, -1)), 1e-15));
    CHECK_THAT(bottom_right.direction, IsNear(glm::normalize(Vec3(1.5, -0.5, -1)), 1e-15));
}

TEST_CASE("perspective_ray: agrees with glm::lookAt and glm::perspective", "[stage2]") {
    INFO(uses("perspective_ray", "stage 1's normalize"));
    INFO(
        "A point on each ray, projected by OpenGL's matrices, must land on its pixel's centre in "
        "normalized device coordinates.");
    for (int k = 0; k < 300; ++k) {
        PortableRandom random(21, static_cast<std::uint64_t>(k));  // case k, on every platform
        const auto [from, at, up, fovy, width, height] = random_camera_input(random);
        const int i = static_cast<int>(random.integer(0, width - 1));
        const int j = static_cast<int>(random.integer(0, height - 1));
        const PerspectiveCamera c = camera_looking(from, at, up, fovy, width, height);
        CAPTURE(k, i, j);
        INFO(text(c));

        const Ray ray = perspective_ray(c, i, j);
        const glm::dmat4 clip_from_world =
            glm::perspective(glm::radians(fovy), double(width) / height, 0.1, 100.0) *
            glm::lookAt(from, at, up);
        const glm::dvec4 clip = clip_from_world * glm::dvec4(ray.origin + ray.direction, 1.0);
        REQUIRE(clip.x / clip.w == Approx(2.0 * (i + 0.5) / width - 1.0).margin(1e-9));
        REQUIRE(clip.y / clip.w == Approx(1.0 - 2.0 * (j + 0.5) / height).margin(1e-9));
    }
}

TEST_CASE("perspective_ray: fovy near 0 gives distinct, finite, nearly parallel rays", "[stage2]") {
    INFO(uses("perspective_ray", "stage 1's normalize"));
    const PerspectiveCamera c = front_camera(1e-6, 64, 64);
    INFO(text(c));
    const Vec3 left = perspective_ray(c, 0, 32).direction;
    const Vec3 right = perspective_ray(c, 63, 32).direction;
    CHECK(is_finite(left));
    CHECK(is_finite(right));
    CHECK(left.x < right.x);
    CHECK(glm::dot(left, Vec3(0, 0, -1)) == Approx(1.0));
}

TEST_CASE("perspective_ray: fovy near 180 gives finite rays that fan out to the side", "[stage2]") {
    INFO(uses("perspective_ray", "stage 1's normalize"));
    const PerspectiveCamera c = front_camera(179.999, 64, 64);
    INFO(text(c));
    const Vec3 corner = perspective_ray(c, 0, 0).direction;
    CHECK(is_finite(corner));
    CHECK(glm::length(corner) == Approx(1.0));
    CHECK(-corner.z < 1e-3);  // almost perpendicular to the view direction
}

TEST_CASE("make_perspective_camera: fovy outside (0, 180) throws", "[stage2]") {
    INFO(uses("make_perspective_camera", "stage 1's orthonormal_frame"));
    REQUIRE_THROWS_AS(make_perspective_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 0.0, 10, 10),
                      std::domain_error);
    REQUIRE_THROWS_AS(make_perspective_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 180.0, 10, 10),
                      std::domain_error);
    REQUIRE_THROWS_AS(make_perspective_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -30.0, 10, 10),
                      std::domain_error);
}

TEST_CASE("make_perspective_camera: up parallel to the view direction throws, not NaN",
          "[stage2]") {
    INFO(uses("make_perspective_camera", "stage 1's orthonormal_frame"));
    INFO("Looking straight down at the floor with +y as \"up\".");
    REQUIRE_THROWS_AS(make_perspective_camera({0, 10, 0}, {0, 0, 0}, {0, 1, 0}, 45, 10, 10),
                      std::domain_error);
}

TEST_CASE("make_perspective_camera: lookfrom equal to lookat throws", "[stage2]") {
    INFO(uses("make_perspective_camera", "stage 1's orthonormal_frame"));
    REQUIRE_THROWS_AS(make_perspective_camera({1, 1, 1}, {1, 1, 1}, {0, 1, 0}, 45, 10, 10),
                      std::domain_error);
}

TEST_CASE("make_perspective_camera: an image without pixels throws", "[stage2]") {
    INFO(uses("make_perspective_camera", "stage 1's orthonormal_frame"));
    REQUIRE_THROWS_AS(make_perspective_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45.0, 0, 10),
                      std::domain_error);
    REQUIRE_THROWS_AS(make_perspective_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45.0, 10, -1),
                      std::domain_error);
}

TEST_CASE("orthographic_ray: parallel rays from pixel centres on the window", "[stage2]") {
    INFO("Window [-1, 1] x [-1, 1] over 2 x 2 pixels: pixel (0, 0) is centred at (-0.5, 0.5).");
    const OrthographicCamera c = front_window(-1, 1, -1, 1, 2, 2);
    INFO(text(c));
    const Ray top_left = orthographic_ray(c, 0, 0);
    const Ray bottom_right = orthographic_ray(c, 1, 1);
    CHECK_THAT(top_left.origin, IsNear(Vec3{-0.5, 0.5, 5}, 1e-15));
    CHECK_THAT(bottom_right.origin, IsNear(Vec3{0.5, -0.5, 5}, 1e-15));
    CHECK_THAT(top_left.direction, IsNear(Vec3{0, 0, -1}, 1e-15));
    CHECK_THAT(bottom_right.direction, IsNear(Vec3{0, 0, -1}, 1e-15));
}

TEST_CASE("orthographic_ray: an off-centre, non-square window", "[stage2]") {
    INFO(
        "Window [0, 4] x [-1, 1] over 4 x 2 pixels: column 3's centre is x = 3.5, row 1's y = "
        "-0.5.");
    const OrthographicCamera c = front_window(0, 4, -1, 1, 4, 2);
    INFO(text(c));
    const Ray bottom_right = orthographic_ray(c, 3, 1);
    const Ray top_left = orthographic_ray(c, 0, 0);
    CHECK_THAT(bottom_right.origin, IsNear(Vec3{3.5, -0.5, 5}, 1e-15));
    CHECK_THAT(top_left.origin, IsNear(Vec3{0.5, 0.5, 5}, 1e-15));
}

TEST_CASE("orthographic_ray: the window follows the camera's frame", "[stage2]") {
    INFO("From +x looking at the origin with up +z: w = +x, u = up x w = +y, v = w x u = +z.");
    const OrthographicCamera c{{5, 0, 0}, {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, -1, 1, -1, 1, 2, 2};
    INFO(text(c));
    const Ray ray = orthographic_ray(c, 1, 0);  // right of centre and above it
    CHECK_THAT(ray.direction, IsNear(Vec3{-1, 0, 0}, 1e-15));
    CHECK_THAT(ray.origin, IsNear(Vec3{5, 0.5, 0.5}, 1e-15));
}

TEST_CASE("make_orthographic_camera: keeps the window and takes the frame of lookfrom, lookat, up",
          "[stage2]") {
    INFO(uses("make_orthographic_camera", "stage 1's orthonormal_frame"));
    INFO(
        "make_orthographic_camera({5, 0, 0}, {0, 0, 0}, {0, 0, 1}, -1, 2, -3, 4, 20, 10): from "
        "+x looking at the origin with up +z, w = +x, u = up x w = +y, v = w x u = +z");
    const OrthographicCamera c =
        make_orthographic_camera({5, 0, 0}, {0, 0, 0}, {0, 0, 1}, -1, 2, -3, 4, 20, 10);
    CHECK(c.eye == Vec3(5, 0, 0));
    CHECK_THAT(c.frame.u, IsNear(Vec3{0, 1, 0}, 1e-15));
    CHECK_THAT(c.frame.v, IsNear(Vec3{0, 0, 1}, 1e-15));
    CHECK_THAT(c.frame.w, IsNear(Vec3{1, 0, 0}, 1e-15));
    CHECK(c.left == -1.0);
    CHECK(c.right == 2.0);
    CHECK(c.bottom == -3.0);
    CHECK(c.top == 4.0);
    CHECK(c.width == 20);
    CHECK(c.height == 10);
}

TEST_CASE("make_orthographic_camera: an empty window throws", "[stage2]") {
    INFO(uses("make_orthographic_camera", "stage 1's orthonormal_frame"));
    REQUIRE_THROWS_AS(make_orthographic_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 1, 1, -1, 1, 2, 2),
                      std::domain_error);
    REQUIRE_THROWS_AS(make_orthographic_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -1, 1, 1, -1, 2, 2),
                      std::domain_error);
}

TEST_CASE("make_orthographic_camera: a NaN or infinite window edge throws", "[stage2]") {
    INFO(uses("make_orthographic_camera", "stage 1's orthonormal_frame"));
    INFO("\"left >= right\" is false for a NaN left, so that test lets NaN through to every ray.");
    const double nan = std::nan("");
    const double inf = HUGE_VAL;
    REQUIRE_THROWS_AS(
        make_orthographic_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, nan, 1, -1, 1, 2, 2),
        std::domain_error);
    REQUIRE_THROWS_AS(
        make_orthographic_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -1, 1, -1, nan, 2, 2),
        std::domain_error);
    REQUIRE_THROWS_AS(
        make_orthographic_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -inf, 1, -1, 1, 2, 2),
        std::domain_error);
}
