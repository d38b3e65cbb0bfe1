// The zip `raystep submit` writes (app/submit/stored_zip.h), byte by byte against APPNOTE.TXT. That
// real unpackers read it is the grader's intake test (grader/grade/tests/submitted_zip_test.cpp)
// and the command tests' `python3 -m zipfile -t`.
#include <cstdint>
#include <stdexcept>
#include <string>

#include "app/submit/stored_zip.h"
#include "base/testing/catch.h"

using namespace raystep;

namespace {

std::uint32_t read32(const std::string& bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i)
        value =
            (value << 8) | static_cast<unsigned char>(bytes.at(at + static_cast<std::size_t>(i)));
    return value;
}

std::uint16_t read16(const std::string& bytes, std::size_t at) {
    return static_cast<std::uint16_t>(static_cast<unsigned char>(bytes.at(at)) |
                                      (static_cast<unsigned char>(bytes.at(at + 1)) << 8));
}

}  // namespace

TEST_CASE("crc32: the check values of CRC-32/ISO-HDLC", "[submit]") {
    CHECK(crc32("123456789") == 0xCBF43926u);
    CHECK(crc32("") == 0u);
    CHECK(crc32("The quick brown fox jumps over the lazy dog") == 0x414FA339u);
}

TEST_CASE("stored_zip: no entries is the 22-byte end record alone", "[submit]") {
    const std::string zip = stored_zip({});
    REQUIRE(zip.size() == 22);
    CHECK(read32(zip, 0) == 0x06054b50u);
    CHECK(read16(zip, 10) == 0);  // entries in all
}

TEST_CASE(
    "stored_zip: each entry's headers hold its CRC, sizes and offset, the bytes stored as they are",
    "[submit]") {
    const std::string first = "double dot();\n";
    const std::string second = "x";
    const std::string zip =
        stored_zip({{"stages/1_vectors/vectors.cpp", first}, {"stages/2_rays/ray.cpp", second}});
    const std::size_t first_name = std::string("stages/1_vectors/vectors.cpp").size();
    const std::size_t second_name = std::string("stages/2_rays/ray.cpp").size();

    // The first local header, then its name and bytes
    CHECK(read32(zip, 0) == 0x04034b50u);
    CHECK(read16(zip, 8) == 0);  // stored
    CHECK(read32(zip, 14) == crc32(first));
    CHECK(read32(zip, 18) == first.size());
    CHECK(read32(zip, 22) == first.size());
    CHECK(zip.substr(30, first_name) == "stages/1_vectors/vectors.cpp");
    CHECK(zip.substr(30 + first_name, first.size()) == first);

    // The second local header right after it
    const std::size_t second_at = 30 + first_name + first.size();
    CHECK(read32(zip, second_at) == 0x04034b50u);
    CHECK(read32(zip, second_at + 14) == crc32(second));

    // The end record points at the central directory, whose second header points back
    const std::size_t end = zip.size() - 22;
    CHECK(read32(zip, end) == 0x06054b50u);
    CHECK(read16(zip, end + 10) == 2);
    const std::size_t directory = read32(zip, end + 16);
    CHECK(directory == second_at + 30 + second_name + second.size());
    CHECK(read32(zip, end + 12) == end - directory);
    CHECK(read32(zip, directory) == 0x02014b50u);
    const std::size_t second_header = directory + 46 + first_name;
    CHECK(read32(zip, second_header) == 0x02014b50u);
    CHECK(read32(zip, second_header + 16) == crc32(second));
    CHECK(read32(zip, second_header + 42) == second_at);
}

TEST_CASE("stored_zip: a name given twice, empty or absolute is refused", "[submit]") {
    CHECK_THROWS_AS(stored_zip({{"a.cpp", "1"}, {"a.cpp", "2"}}), std::invalid_argument);
    CHECK_THROWS_AS(stored_zip({{"", "1"}}), std::invalid_argument);
    CHECK_THROWS_AS(stored_zip({{"/etc/a.cpp", "1"}}), std::invalid_argument);
}
