#include "base/image/image_io.h"

#include <filesystem>
#include <stdexcept>

#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"

using namespace raystep;

namespace {

// A 3 x 2 image whose pixels are all different, with the top-left one red.
Image pattern() {
    Image image(3, 2);
    image.set(0, 0, {1, 0, 0});
    image.set(1, 0, {0, 1, 0});
    image.set(2, 0, {0, 0, 1});
    image.set(0, 1, {0.5, 0.5, 0.5});
    image.set(1, 1, {2.0, -1.0, 0.25});  // out of [0, 1]: clamped in 8-bit files
    image.set(2, 1, {0, 0, 0});
    return image;
}

}  // namespace

TEST_CASE("write_image: PNG round trip keeps row 0 at the top and clamps to [0, 1]", "[base]") {
    const testing::ScratchFolder scratch("image-io-test");
    const std::filesystem::path file = scratch.path() / "pattern.png";
    write_image(pattern(), file);
    const Image back = read_image(file);
    REQUIRE(back.width() == 3);
    REQUIRE(back.height() == 2);
    CHECK(back.at(0, 0) == Color(1, 0, 0));
    CHECK(back.at(2, 0) == Color(0, 0, 1));
    CHECK(back.at(0, 1).r == Approx(128.0 / 255.0));  // 0.5 rounds to 128 of 255
    CHECK(back.at(1, 1).r == 1.0);
    CHECK(back.at(1, 1).g == 0.0);
    CHECK(back.at(1, 1).b == Approx(64.0 / 255.0));
}

TEST_CASE("write_image: EXR keeps the floats as they are", "[base]") {
    const testing::ScratchFolder scratch("image-io-test");
    const std::filesystem::path file = scratch.path() / "pattern.exr";
    write_image(pattern(), file);
    const Image back = read_image(file);
    CHECK(back.at(1, 1) == Color(2.0, -1.0, 0.25));
    CHECK(back.at(0, 1) == Color(0.5));
}

TEST_CASE("write_image: an unknown format is an error naming the file", "[base]") {
    const testing::ScratchFolder scratch("image-io-test");
    CHECK_THROWS_WITH(write_image(pattern(), scratch.path() / "pattern.unknown-format"),
                      Catch::Matchers::Contains("pattern.unknown-format"));
}

TEST_CASE("read_image: a missing file is an error naming it", "[base]") {
    const testing::ScratchFolder scratch("image-io-test");
    CHECK_THROWS_AS(read_image(scratch.path() / "missing.png"), std::runtime_error);
}
