// Reading the protocol's values is strict (app/protocol/probe_json.h): what the other side sent is
// taken as it is or refused, never bent into something else.

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "app/protocol/probe_json.h"
#include "base/testing/catch.h"

using raystep::probe::field;
using raystep::probe::integer_from;
using raystep::probe::Json;

TEST_CASE("integer_from: a whole number that fits an int, and nothing else", "[app]") {
    CHECK(integer_from(Json(160)) == 160);
    CHECK(integer_from(Json(-3)) == -3);
    CHECK(integer_from(Json(std::numeric_limits<int>::max())) == std::numeric_limits<int>::max());
    CHECK(integer_from(Json(std::numeric_limits<int>::min())) == std::numeric_limits<int>::min());
    // 2^31 would wrap to a negative width; 2.5 would be cut to 2; neither is what was sent.
    CHECK_THROWS_AS(integer_from(Json(std::int64_t{1} << 31)), std::invalid_argument);
    CHECK_THROWS_AS(integer_from(Json(-(std::int64_t{1} << 31) - 1)), std::invalid_argument);
    CHECK_THROWS_AS(integer_from(Json(std::numeric_limits<std::uint64_t>::max())),
                    std::invalid_argument);
    CHECK_THROWS_AS(integer_from(Json(2.5)), std::invalid_argument);
    CHECK_THROWS_AS(integer_from(Json(2.0)), std::invalid_argument);
    CHECK_THROWS_AS(integer_from(Json("7")), std::invalid_argument);
    CHECK_THROWS_AS(integer_from(Json(true)), std::invalid_argument);
}

TEST_CASE("field: an object's field, or an error naming the one that is missing", "[app]") {
    const Json object = {{"width", 4}};
    CHECK(field(object, "width") == 4);
    CHECK_THROWS_WITH(field(object, "height"), "expected a field 'height'");
    CHECK_THROWS_WITH(field(Json::array({1, 2}), "width"), "expected a field 'width'");
}

TEST_CASE("nested_too_deep: refuses a line nested past the protocol's depth, wherever it nests",
          "[app]") {
    const auto nested = [](int depth, char open, char close) {
        return std::string(static_cast<std::size_t>(depth), open) +
               std::string(static_cast<std::size_t>(depth), close);
    };
    CHECK_FALSE(raystep::probe::nested_too_deep(R"({"id":0,"result":[[1,2],[3,{"a":[4]}]]})"));
    CHECK_FALSE(raystep::probe::nested_too_deep(nested(raystep::probe::kDeepestNesting, '[', ']')));
    CHECK(raystep::probe::nested_too_deep(nested(raystep::probe::kDeepestNesting + 1, '[', ']')));
    CHECK(raystep::probe::nested_too_deep(R"({"id":0,"result":)" + nested(300000, '[', ']') + "}"));
    // Brackets inside strings, escaped quotes included, are text, not nesting
    const std::string quoted = "\"" + nested(100, '[', ']') + "\\\"" + nested(100, '{', '}') + "\"";
    CHECK_FALSE(raystep::probe::nested_too_deep(R"({"id":0,"threw":{"message":)" + quoted + "}}"));
}
