// Public tests for stage 11, reading an image at texture coordinates. Run them with
// `ctest --preset student -L stage11`, one function's with
// `build/student/bin/raystep_stage11_tests "texture_bilinear:*"`.

#include "base/testing/catch.h"
#include "base/testing/filled_image.h"
#include "base/testing/vec3_matchers.h"
#include "stages/11_surface_detail/surface_detail.h"

using namespace raystep;
using raystep::testing::filled_image;
using raystep::testing::IsNear;

namespace {

// A 2 x 2 image, one colour a texel: row 0 is the top.
const Color kTopLeft{1, 0, 0}, kTopRight{0, 1, 0}, kBottomLeft{0, 0, 1}, kBottomRight{1, 1, 1};

Image four_texels() {
    Image image(2, 2);
    image.set(0, 0, kTopLeft);
    image.set(1, 0, kTopRight);
    image.set(0, 1, kBottomLeft);
    image.set(1, 1, kBottomRight);
    return image;
}

}  // namespace

TEST_CASE("wrap_texel: indices inside the image are themselves in every mode", "[stage11]") {
    for (WrapMode wrap : {WrapMode::repeat, WrapMode::clamp, WrapMode::mirror}) {
        for (int i = 0; i < 4; ++i) {
            CAPTURE(static_cast<int>(wrap), i);
            CHECK(wrap_texel(i, 4, wrap) == i);
        }
    }
}

TEST_CASE("wrap_texel: repeat starts the image again, on both sides", "[stage11]") {
    CHECK(wrap_texel(4, 4, WrapMode::repeat) == 0);
    CHECK(wrap_texel(9, 4, WrapMode::repeat) == 1);
    CHECK(wrap_texel(-1, 4, WrapMode::repeat) == 3);
    CHECK(wrap_texel(-4, 4, WrapMode::repeat) == 0);
    CHECK(wrap_texel(-5, 4, WrapMode::repeat) == 3);
}

TEST_CASE("wrap_texel: clamp holds the edge texel", "[stage11]") {
    CHECK(wrap_texel(4, 4, WrapMode::clamp) == 3);
    CHECK(wrap_texel(1000, 4, WrapMode::clamp) == 3);
    CHECK(wrap_texel(-1, 4, WrapMode::clamp) == 0);
}

TEST_CASE("wrap_texel: mirror reflects at each edge, the edge texel twice", "[stage11]") {
    // ... 1 0 | 0 1 2 3 | 3 2 1 0 | 0 1 ...
    const int expected[] = {1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0, 1};
    for (int k = 0; k < 12; ++k) {
        const int i = k - 2;
        CAPTURE(i);
        CHECK(wrap_texel(i, 4, WrapMode::mirror) == expected[k]);
    }
}

TEST_CASE("texture_nearest: v = 0 is the bottom row, u = 0 the left column", "[stage11]") {
    const Image image = four_texels();
    CHECK_THAT(texture_nearest(image, {0.25, 0.75}, WrapMode::clamp), IsNear(kTopLeft, 0.0));
    CHECK_THAT(texture_nearest(image, {0.75, 0.75}, WrapMode::clamp), IsNear(kTopRight, 0.0));
    CHECK_THAT(texture_nearest(image, {0.25, 0.25}, WrapMode::clamp), IsNear(kBottomLeft, 0.0));
    CHECK_THAT(texture_nearest(image, {0.75, 0.25}, WrapMode::clamp), IsNear(kBottomRight, 0.0));
}

TEST_CASE("texture_nearest: beyond the edge, by the wrap mode", "[stage11]") {
    const Image image = four_texels();
    // u = 1.25 is column 2: column 0 again when repeated, column 1 when clamped.
    CHECK_THAT(texture_nearest(image, {1.25, 0.75}, WrapMode::repeat), IsNear(kTopLeft, 0.0));
    CHECK_THAT(texture_nearest(image, {1.25, 0.75}, WrapMode::clamp), IsNear(kTopRight, 0.0));
    CHECK_THAT(texture_nearest(image, {1.25, 0.75}, WrapMode::mirror), IsNear(kTopRight, 0.0));
    // v = -0.25 is row 2, below the image: row 0 repeated.
    CHECK_THAT(texture_nearest(image, {0.25, -0.25}, WrapMode::repeat), IsNear(kTopLeft, 0.0));
    // u = -0.25 is column floor(-0.5) = -1, the last column repeated; truncating -0.5 to 0
    // would read the first.
    CHECK_THAT(texture_nearest(image, {-0.25, 0.75}, WrapMode::repeat), IsNear(kTopRight, 0.0));
}

TEST_CASE("texture_bilinear: a texel's centre reads that texel", "[stage11]") {
    const Image image = four_texels();
    CHECK_THAT(texture_bilinear(image, {0.25, 0.75}, WrapMode::clamp), IsNear(kTopLeft, 1e-15));
    CHECK_THAT(texture_bilinear(image, {0.75, 0.25}, WrapMode::repeat),
               IsNear(kBottomRight, 1e-15));
}

TEST_CASE("texture_bilinear: between centres, the texels blended by distance", "[stage11]") {
    const Image image = four_texels();
    // Halfway between the top row's centres: their mean.
    CHECK_THAT(texture_bilinear(image, {0.5, 0.75}, WrapMode::clamp),
               IsNear(0.5 * (kTopLeft + kTopRight), 1e-15));
    // A quarter of the way from the top-left centre towards the bottom-left one: x = 0, y = 0.25.
    CHECK_THAT(texture_bilinear(image, {0.25, 0.625}, WrapMode::clamp),
               IsNear(0.75 * kTopLeft + 0.25 * kBottomLeft, 1e-15));
    // The image's centre: all four alike.
    CHECK_THAT(texture_bilinear(image, {0.5, 0.5}, WrapMode::clamp),
               IsNear(0.25 * (kTopLeft + kTopRight + kBottomLeft + kBottomRight), 1e-15));
}

TEST_CASE("texture_bilinear: at the edge, repeat blends with the far side and clamp does not",
          "[stage11]") {
    const Image image = four_texels();
    // u = 0 is halfway between column 0's centre and, repeated, column 1's (x = -0.5).
    CHECK_THAT(texture_bilinear(image, {0.0, 0.75}, WrapMode::repeat),
               IsNear(0.5 * (kTopLeft + kTopRight), 1e-15));
    CHECK_THAT(texture_bilinear(image, {0.0, 0.75}, WrapMode::clamp), IsNear(kTopLeft, 1e-15));
}

TEST_CASE("texture_bilinear: an image of one colour reads that colour everywhere", "[stage11]") {
    // The four weights sum to 1 wherever (u, v) is.
    const Color grey{0.3, 0.5, 0.7};
    const Image image = filled_image(5, 3, grey);
    for (const Vec2& uv : {Vec2(0.0, 0.0), Vec2(0.13, 0.91), Vec2(-2.7, 5.3), Vec2(1.0, 1.0)}) {
        CAPTURE(uv.x, uv.y);
        CHECK_THAT(texture_bilinear(image, uv, WrapMode::repeat), IsNear(grey, 1e-7));
    }
}
