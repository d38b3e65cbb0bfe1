// Public tests for stage 11, normal mapping and bump mapping. Run them with
// `ctest --preset student -L stage11`, one function's with
// `build/student/bin/raystep_stage11_tests "bump_normal:*"`.

#include <stdexcept>

#include <glm/geometric.hpp>

#include "base/testing/catch.h"
#include "base/testing/filled_image.h"
#include "base/testing/number_matchers.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/11_surface_detail/surface_detail.h"

using namespace raystep;
using raystep::testing::filled_image;
using raystep::testing::IsNear;
using raystep::testing::uses;

namespace {

// A frame turned from the axes, so that a normal left in the map's own axes fails.
const TangentFrame kFrame{{0, 1, 0}, {0, 0, 1}, {1, 0, 0}};

// A width x height height map whose bilinear lookup is h = a u + b v inside the image: texel
// (i, j)'s centre sits at u = (i + 0.5) / W, v = 1 - (j + 0.5) / H.
Image ramp(int width, int height, double a, double b) {
    Image image(width, height);
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            const double u = (i + 0.5) / width;
            const double v = 1.0 - (j + 0.5) / height;
            image.set(i, j, Color(a * u + b * v));
        }
    }
    return image;
}

}  // namespace

TEST_CASE("normal_from_map: the flat texel (0.5, 0.5, 1) holds the frame's normal", "[stage11]") {
    CHECK_THAT(normal_from_map(kFrame, {0.5, 0.5, 1.0}), IsNear(kFrame.normal, 1e-15));
}

TEST_CASE("normal_from_map: red is along the tangent and green along the bitangent", "[stage11]") {
    CHECK_THAT(normal_from_map(kFrame, {1.0, 0.5, 0.5}), IsNear(kFrame.tangent, 1e-15));
    CHECK_THAT(normal_from_map(kFrame, {0.5, 1.0, 0.5}), IsNear(kFrame.bitangent, 1e-15));
    // (0.8, 0.5, 0.9) is (0.6, 0, 0.8) in the frame: already unit.
    CHECK_THAT(normal_from_map(kFrame, {0.8, 0.5, 0.9}),
               IsNear(0.6 * kFrame.tangent + 0.8 * kFrame.normal, 1e-15));
}

TEST_CASE("normal_from_map: a texel of any length gives a unit normal", "[stage11]") {
    // 8-bit maps store 2r - 1 to 1/255: the decoded vector is near unit, not unit.
    const Vec3 n = normal_from_map(kFrame, {0.7, 0.2, 0.6});
    CHECK_THAT(glm::length(n), IsNear(1.0, 1e-15));
}

TEST_CASE("normal_from_map: the texel (0.5, 0.5, 0.5) throws domain_error", "[stage11]") {
    CHECK_THROWS_AS(normal_from_map(kFrame, {0.5, 0.5, 0.5}), std::domain_error);
}

TEST_CASE("height_slopes: a flat map has no slope", "[stage11]") {
    INFO(uses("height_slopes", "texture_bilinear"));
    const Vec2 slopes =
        height_slopes(filled_image(8, 8, Color(0.4)), {0.3, 0.6}, WrapMode::repeat, 2.0);
    CHECK_THAT(slopes.x, IsNear(0.0, 1e-12));
    CHECK_THAT(slopes.y, IsNear(0.0, 1e-12));
}

TEST_CASE("height_slopes: a ramp's slopes, times the scale", "[stage11]") {
    INFO(uses("height_slopes", "texture_bilinear"));
    // h = 0.5 u + 0.25 v inside the image, scaled by 3: slopes 1.5 and 0.75, v upwards.
    const Image map = ramp(16, 8, 0.5, 0.25);
    const Vec2 slopes = height_slopes(map, {0.4, 0.45}, WrapMode::clamp, 3.0);
    CHECK_THAT(slopes.x, IsNear(1.5, 1e-6));
    CHECK_THAT(slopes.y, IsNear(0.75, 1e-6));
}

TEST_CASE("bump_normal: no slope leaves the normal", "[stage11]") {
    const Vec3 n{0, 0, 1};
    CHECK_THAT(bump_normal({{1, 0, 0}, {0, 1, 0}}, n, {0.0, 0.0}), IsNear(n, 1e-15));
}

TEST_CASE("bump_normal: a slope along u tips the normal back against it", "[stage11]") {
    // (1, 0, a) x (0, 1, 0) = (-a, 0, 1): rising towards +u, the surface faces back towards -u.
    const double a = 0.75;
    CHECK_THAT(bump_normal({{1, 0, 0}, {0, 1, 0}}, {0, 0, 1}, {a, 0.0}),
               IsNear(glm::normalize(Vec3(-a, 0, 1)), 1e-15));
    CHECK_THAT(bump_normal({{1, 0, 0}, {0, 1, 0}}, {0, 0, 1}, {0.0, a}),
               IsNear(glm::normalize(Vec3(0, -a, 1)), 1e-15));
}

TEST_CASE("bump_normal: stays on the normal's side when u x v points the other way", "[stage11]") {
    // dp/du x dp/dv = -z here, while the surface's normal is +z: the bumped normal is turned.
    // (0, 1, 0.5) x (1, 0, 0) = (0, 0.5, -1), turned: rising towards +u, which is +y here.
    const Vec3 bumped = bump_normal({{0, 1, 0}, {1, 0, 0}}, {0, 0, 1}, {0.5, 0.0});
    CHECK_THAT(bumped, IsNear(glm::normalize(Vec3(0, -0.5, 1)), 1e-15));
}
