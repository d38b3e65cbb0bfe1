#include "grader/report/data_url.h"

#include <fstream>

#include "app/protocol/base64.h"
#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"

using namespace raystep::grade;
using raystep::base64;

namespace {

// A file holding bytes, in a scratch folder of its own.
std::filesystem::path write_file(const raystep::testing::ScratchFolder& folder,
                                 const std::string& name, const std::string& bytes) {
    const std::filesystem::path path = folder.path() / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

}  // namespace

TEST_CASE("base64: RFC 4648's test vectors, padding included", "[report]") {
    // RFC 4648, section 10.
    CHECK(base64("") == "");
    CHECK(base64("f") == "Zg==");
    CHECK(base64("fo") == "Zm8=");
    CHECK(base64("foo") == "Zm9v");
    CHECK(base64("foob") == "Zm9vYg==");
    CHECK(base64("fooba") == "Zm9vYmE=");
    CHECK(base64("foobar") == "Zm9vYmFy");
    // Every bit pattern of the alphabet's ends, and bytes above 127.
    CHECK(base64(std::string("\x00\x10\x83\x10\x51\x87\x20\x92\x8b\x30\xd3\x8f\x41\x14\x93\x51"
                             "\x55\x97\x61\x96\x9b\x71\xd7\x9f\x82\x18\xa3\x92\x59\xa7\xa2\x9a"
                             "\xab\xb2\xdb\xaf\xc3\x1c\xb3\xd3\x5d\xb7\xe3\x9e\xbb\xf3\xdf\xbf",
                             48)) ==
          "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/");
}

TEST_CASE("image_data_url: an image file as a data URL of its media type", "[report]") {
    const std::string bytes("\x89PNG\r\n\x1a\n\x00\x01\xff", 11);
    const raystep::testing::ScratchFolder scratch("data-url-test");
    const auto png = write_file(scratch, "image.png", bytes);
    CHECK(image_data_url(png, 1000) == "data:image/png;base64," + base64(bytes));
    const auto jpeg = write_file(scratch, "photo.JPG", "jpeg");
    CHECK(image_data_url(jpeg, 1000) == "data:image/jpeg;base64," + base64("jpeg"));
}

TEST_CASE("image_data_url: nothing for a missing file, another type, or one too large",
          "[report]") {
    CHECK_FALSE(image_data_url("/nonexistent/raystep/image.png", 1000));
    const raystep::testing::ScratchFolder scratch("data-url-test");
    const auto text = write_file(scratch, "page.html", "<script>alert(1)</script>");
    CHECK_FALSE(image_data_url(text, 1000));
    const auto large = write_file(scratch, "large.png", std::string(2000, 'x'));
    CHECK_FALSE(image_data_url(large, 1999));
    CHECK(image_data_url(large, 2000));
}
