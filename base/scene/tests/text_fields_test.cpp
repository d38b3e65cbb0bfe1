#include "base/scene/text_fields.h"

#include <cstdint>
#include <string>
#include <vector>

#include "base/errors/input_error.h"
#include "base/testing/catch.h"

using namespace raystep;

namespace {

const std::string kFile = "test.txt";

double number(const std::string& token) {
    return parse_finite_number(token, {kFile, 7}, "the value");
}

long count(const std::string& token) {
    return parse_count(token, {kFile, 7}, "the count");
}

std::uint64_t seed(const std::string& token) {
    return parse_unsigned64(token, {kFile, 7}, "the seed");
}

}  // namespace

TEST_CASE("split_fields: splits on any white space and drops comments", "[base]") {
    std::vector<std::string_view> fields;
    const std::string line = "  sphere\t1  2 3 # the rest is a comment\r";
    split_fields(line, fields);
    REQUIRE(fields.size() == 4);
    CHECK(fields[0] == "sphere");
    CHECK(fields[3] == "3");
    split_fields("# only a comment", fields);
    CHECK(fields.empty());
    split_fields("", fields);
    CHECK(fields.empty());
}

TEST_CASE("parse_finite_number: reads decimal, exponent and signed forms", "[base]") {
    CHECK(number("1.5") == 1.5);
    CHECK(number("-2e-3") == -2e-3);
    CHECK(number("+.25") == 0.25);
    CHECK(number("1e-400") == 0.0);  // underflow is the nearest double, not an error
}

TEST_CASE("parse_finite_number: rejects text, trailing characters, inf, nan and overflow",
          "[base]") {
    CHECK_THROWS_WITH(number("abc"), "test.txt:7: the value 'abc' is not a number");
    CHECK_THROWS_WITH(number("1.5x"), "test.txt:7: the value '1.5x' is not a number");
    CHECK_THROWS_WITH(number("2,5"), "test.txt:7: the value '2,5' is not a number");
    CHECK_THROWS_WITH(number("inf"), "test.txt:7: the value 'inf' is not finite");
    CHECK_THROWS_WITH(number("nan"), "test.txt:7: the value 'nan' is not finite");
    CHECK_THROWS_WITH(number("1e999"), "test.txt:7: the value '1e999' is too large for a double");
}

TEST_CASE("parse_count: reads whole non-negative numbers only", "[base]") {
    CHECK(count("0") == 0);
    CHECK(count("42") == 42);
    CHECK_THROWS_WITH(count("2.5"), "test.txt:7: the count '2.5' is not a whole number");
    CHECK_THROWS_WITH(count("-1"), "test.txt:7: the count '-1' must not be negative");
    CHECK_THROWS_WITH(count("99999999999999999999999"),
                      "test.txt:7: the count '99999999999999999999999' is too large");
    CHECK_THROWS_AS(count("x"), InputError);
}

TEST_CASE("parse_unsigned64: reads the whole 64-bit range and nothing beyond it", "[base]") {
    CHECK(seed("0") == 0);
    CHECK(seed("18446744073709551615") == 18446744073709551615ull);
    CHECK_THROWS_WITH(seed("18446744073709551616"),
                      "test.txt:7: the seed '18446744073709551616' is above "
                      "18446744073709551615, the largest 64-bit number");
    // A sign is refused rather than wrapped: strtoull would read "-1" as 2^64 - 1.
    CHECK_THROWS_WITH(seed("-1"),
                      "test.txt:7: the seed '-1' is not a whole number from 0 to "
                      "18446744073709551615");
    CHECK_THROWS_AS(seed("+1"), InputError);
    CHECK_THROWS_AS(seed("1.5"), InputError);
    CHECK_THROWS_AS(seed("0x10"), InputError);
    CHECK_THROWS_AS(seed(""), InputError);
}
