// Public tests for stage 8, antialiasing: rays through any point of the film, and a pixel's mean
// over its samples. Run them with `ctest --preset student -L stage8`, one function's with
// `build/student/bin/raystep_stage8_tests "pixel_colour:*"`.
//
// The rays are held against your stage-2 perspective_ray and orthographic_ray at pixel centres,
// and against hand-worked points elsewhere. pixel_colour is tested without a scene: the
// FilmRadiance is a lambda that plays the image (a constant, an edge) and records where it is
// asked. Each test calls your function before its CHECKs, so a stub is reported once. A loop over
// pixels or points stops at the first that fails, and a function built from others names them:
// fix theirs first.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "base/testing/catch.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/8_sampling/sampling.h"

using namespace raystep;
using raystep::testing::IsNear;
using raystep::testing::uses;

namespace {

const double kInf = std::numeric_limits<double>::infinity();

std::string text(const Vec2& p) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "(%.17g, %.17g)", p.x, p.y);
    return buffer;
}

// Looking down -z from the origin with y up, fovy 90 over 4 x 4 pixels: the image plane at
// distance 1 spans [-1, 1] in x and y, so each pixel is 0.5 wide there, and film point (x, y)
// looks along ((x - 2) / 2, (2 - y) / 2, -1).
PerspectiveCamera square_camera() {
    return make_perspective_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90.0, 4, 4);
}

// The direction through film point (x, y) of square_camera, by the formula above.
Vec3 square_camera_direction(double x, double y) {
    const Vec3 d{(x - 2) / 2, (2 - y) / 2, -1};
    return d / std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

}  // namespace

TEST_CASE("perspective_ray_through: at each pixel centre, stage 2's perspective_ray", "[stage8]") {
    INFO(uses("perspective_ray_through", "stage 2's camera and stage 1's normalize"));
    INFO("film = (i + 0.5, j + 0.5) must give your perspective_ray(camera, i, j).");
    const PerspectiveCamera camera =
        make_perspective_camera({1, 2, 3}, {0, 0, 0}, {0, 1, 0}, 60.0, 5, 3);
    for (int j = 0; j < camera.height; ++j) {
        for (int i = 0; i < camera.width; ++i) {
            CAPTURE(i, j);
            const Ray got = perspective_ray_through(camera, {i + 0.5, j + 0.5});
            const Ray expected = perspective_ray(camera, i, j);
            REQUIRE(got.origin == expected.origin);
            REQUIRE_THAT(got.direction, IsNear(expected.direction, 1e-15));
            REQUIRE(got.t_min == 0.0);
            REQUIRE(got.t_max == kInf);
        }
    }
}

TEST_CASE("perspective_ray_through: a pixel's corners and inner points, worked by hand",
          "[stage8]") {
    INFO(uses("perspective_ray_through", "stage 2's camera and stage 1's normalize"));
    INFO(
        "fovy 90 over 4 x 4 pixels, eye at the origin looking down -z: film (x, y) looks along "
        "((x - 2) / 2, (2 - y) / 2, -1), normalized. (0, 0) is the image's top left corner, "
        "(2, 2) its centre, (4, 4) its bottom right; half a pixel right of the centre is a "
        "quarter of the way to the edge.");
    const PerspectiveCamera camera = square_camera();
    for (const Vec2& film :
         {Vec2{0, 0}, Vec2{1, 0}, Vec2{2, 2}, Vec2{2.5, 2}, Vec2{4, 4}, Vec2{0.25, 3.75}}) {
        INFO("film " << text(film));
        const Ray ray = perspective_ray_through(camera, film);
        REQUIRE(ray.origin == Vec3(0, 0, 0));
        REQUIRE_THAT(ray.direction, IsNear(square_camera_direction(film.x, film.y), 1e-15));
    }
}

TEST_CASE("orthographic_ray_through: at each pixel centre, stage 2's orthographic_ray",
          "[stage8]") {
    INFO(uses("orthographic_ray_through", "stage 2's camera"));
    const OrthographicCamera camera =
        make_orthographic_camera({1, 2, 3}, {0, 0, 0}, {0, 1, 0}, -2, 3, -1, 1, 5, 4);
    for (int j = 0; j < camera.height; ++j) {
        for (int i = 0; i < camera.width; ++i) {
            CAPTURE(i, j);
            const Ray got = orthographic_ray_through(camera, {i + 0.5, j + 0.5});
            const Ray expected = orthographic_ray(camera, i, j);
            REQUIRE_THAT(got.origin, IsNear(expected.origin, 1e-15));
            REQUIRE_THAT(got.direction, IsNear(expected.direction, 1e-15));
            REQUIRE(got.t_min == 0.0);
            REQUIRE(got.t_max == kInf);
        }
    }
}

TEST_CASE("orthographic_ray_through: the origin moves across the window with the film point",
          "[stage8]") {
    INFO(uses("orthographic_ray_through", "stage 2's camera"));
    INFO(
        "Window [-2, 2] x [-1, 1] over 4 x 2 pixels, eye at the origin looking down -z: one unit "
        "per pixel, film (x, y) starts at (x - 2, 1 - y, 0) and goes along (0, 0, -1).");
    const OrthographicCamera camera =
        make_orthographic_camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, -2, 2, -1, 1, 4, 2);
    for (const Vec2& film : {Vec2{0, 0}, Vec2{4, 2}, Vec2{1.25, 0.5}, Vec2{3.75, 1.875}}) {
        INFO("film " << text(film));
        const Ray ray = orthographic_ray_through(camera, film);
        REQUIRE_THAT(ray.origin, IsNear(Vec3{film.x - 2, 1 - film.y, 0}, 1e-15));
        REQUIRE_THAT(ray.direction, IsNear(Vec3{0, 0, -1}, 1e-15));
    }
}

TEST_CASE("pixel_colour: a constant image gives that constant, for every pattern", "[stage8]") {
    INFO(uses("pixel_colour", "samples"));
    const Color c{0.25, 0.5, 1};
    const FilmRadiance constant = [c](const Vec2&) { return c; };
    for (const auto& [pattern, count] :
         {std::pair{SamplePattern::jittered, 16}, std::pair{SamplePattern::regular, 4},
          std::pair{SamplePattern::random, 5}}) {
        CAPTURE(static_cast<int>(pattern), count);
        RandomStream random(7, 0);
        const Color got = pixel_colour(constant, 2, 1, pattern, count, random);
        REQUIRE_THAT(got, IsNear(c, 1e-15));
    }
}

TEST_CASE("pixel_colour: asks the radiance count times, at points inside the pixel", "[stage8]") {
    INFO(uses("pixel_colour", "samples"));
    INFO(
        "Pixel (3, 5) is the film square [3, 4) x [5, 6). Jittered with 9 samples: 9 calls, one "
        "in each third of the pixel across and down; random with 7: 7 calls.");
    for (const auto& [pattern, count] :
         {std::pair{SamplePattern::jittered, 9}, std::pair{SamplePattern::random, 7}}) {
        CAPTURE(static_cast<int>(pattern), count);
        std::vector<Vec2> asked;
        const FilmRadiance record = [&asked](const Vec2& film) {
            asked.push_back(film);
            return Color(0.0);
        };
        RandomStream random(7, 1);
        pixel_colour(record, 3, 5, pattern, count, random);
        REQUIRE(asked.size() == static_cast<std::size_t>(count));
        std::vector<int> per_stratum(9, 0);
        for (const Vec2& film : asked) {
            INFO("asked at film " << text(film));
            REQUIRE(film.x >= 3.0);
            REQUIRE(film.x < 4.0);
            REQUIRE(film.y >= 5.0);
            REQUIRE(film.y < 6.0);
            const int a = std::min(2, static_cast<int>((film.x - 3.0) * 3));
            const int b = std::min(2, static_cast<int>((film.y - 5.0) * 3));
            if (a >= 0 && b >= 0) ++per_stratum[static_cast<std::size_t>(b * 3 + a)];
        }
        if (pattern == SamplePattern::jittered) REQUIRE(per_stratum == std::vector<int>(9, 1));
    }
}

TEST_CASE("pixel_colour: an edge along the pixel's middle gives exactly 1/2 when jittered",
          "[stage8]") {
    INFO(uses("pixel_colour", "samples"));
    INFO(
        "White left of x = i + 0.5, black right of it. 4 x 4 jittered samples: the edge runs "
        "along a stratum boundary, 2 columns of 4 are white whatever the jitter: 8 / 16 = 0.5.");
    const int i = 6;
    const FilmRadiance edge = [](const Vec2& film) {
        return film.x < i + 0.5 ? Color(1.0) : Color(0.0);
    };
    for (std::uint64_t stream = 0; stream < 20; ++stream) {
        CAPTURE(stream);
        RandomStream random(7, stream);
        const Color got = pixel_colour(edge, i, 2, SamplePattern::jittered, 16, random);
        REQUIRE(got == Color(0.5));
    }
}

TEST_CASE("pixel_colour: a diagonal edge through the centre gives 1/2 within 1/16 when jittered",
          "[stage8]") {
    INFO(uses("pixel_colour", "samples"));
    INFO(
        "White where (x - i) + (y - j) < 1, half the pixel. 8 x 8 jittered samples: 28 strata lie "
        "wholly on the white side, 28 on the black, and the 8 on the diagonal are cut in half, "
        "each white or black by its jitter. So the mean is (28 + k) / 64 with k from 0 to 8: "
        "1/2 within 4/64 = 1/16, always. Uniform random samples have no such bound.");
    const int i = 3;
    const int j = 4;
    const FilmRadiance diagonal = [](const Vec2& film) {
        return (film.x - i) + (film.y - j) < 1.0 ? Color(1.0) : Color(0.0);
    };
    for (std::uint64_t stream = 0; stream < 20; ++stream) {
        CAPTURE(stream);
        RandomStream random(7, stream);
        const Color got = pixel_colour(diagonal, i, j, SamplePattern::jittered, 64, random);
        CAPTURE(got.x);
        REQUIRE(std::abs(got.x - 0.5) <= 1.0 / 16);
        REQUIRE(got.x == got.y);
        REQUIRE(got.x == got.z);
    }
}
