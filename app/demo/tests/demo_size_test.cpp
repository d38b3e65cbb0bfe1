#include "app/demo/demo_size.h"

#include <stdexcept>

#include "base/testing/catch.h"

using namespace raystep;

TEST_CASE("parse_demo_size: WIDTHxHEIGHT, from 320x240 to a 4K projector's 3840x2160", "[app]") {
    CHECK(parse_demo_size("1920x1080").width == 1920);
    CHECK(parse_demo_size("1920x1080").height == 1080);
    CHECK(parse_demo_size("1024X768").width == 1024);
    CHECK(parse_demo_size("320x240").height == 240);
    CHECK(parse_demo_size("3840x2160").width == 3840);
}

TEST_CASE("parse_demo_size: a size it cannot draw at is refused, saying what is wrong", "[app]") {
    CHECK_THROWS_WITH(parse_demo_size("1920"),
                      "'1920' has no 'x' between width and height: "
                      "write WIDTHxHEIGHT in pixels, such as 1920x1080");
    for (const char* text : {"x1080", "1920x", "-640x480", "640x-480", "1920.0x1080", " 640x480",
                             "640 x 480", "640x480x2", "0x1e3"}) {
        CAPTURE(text);
        CHECK_THROWS_WITH(parse_demo_size(text),
                          Catch::Matchers::Contains("is not two whole numbers"));
    }
    CHECK_THROWS_WITH(parse_demo_size("0x0"), Catch::Matchers::StartsWith("'0x0' is too small"));
    CHECK_THROWS_WITH(parse_demo_size("1920x200"),
                      Catch::Matchers::StartsWith("'1920x200' is too small"));
    CHECK_THROWS_WITH(parse_demo_size("3841x2160"),
                      Catch::Matchers::StartsWith("'3841x2160' is too large"));
    // Digits beyond an int are too large, not an overflow into a size that passes
    CHECK_THROWS_WITH(parse_demo_size("4294967936x1080"),
                      Catch::Matchers::StartsWith("'4294967936x1080' is too large"));
}
