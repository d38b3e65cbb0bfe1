// Slicing a class for batch --shard I/N (grader/grade/shard.h).

#include <stdexcept>
#include <vector>

#include "base/testing/catch.h"

#include "grader/grade/shard.h"

using raystep::grade::parse_shard;
using raystep::grade::Shard;

TEST_CASE("parse_shard: reads I/N with I from 1 to N", "[grader]") {
    const Shard shard = parse_shard("2/8");
    CHECK(shard.index == 2);
    CHECK(shard.count == 8);
    CHECK(parse_shard("1/1").count == 1);
    CHECK(parse_shard("8/8").index == 8);
}

TEST_CASE("parse_shard: refuses what is not I/N with 1 <= I <= N", "[grader]") {
    for (const char* text : {"0/3", "4/3", "1/0", "3", "a/b", "1/3/5", "-1/3", " 1/3", ""}) {
        INFO(text);
        CHECK_THROWS_AS(parse_shard(text), std::invalid_argument);
    }
}

TEST_CASE("Shard: N shards hold every submission once, round robin, within one of each other",
          "[grader]") {
    const int count = 3;
    std::vector<int> owners(10, 0);
    std::vector<int> sizes(count, 0);
    for (int index = 1; index <= count; ++index) {
        for (std::size_t k = 0; k < owners.size(); ++k) {
            if (Shard{index, count}.holds(k)) {
                ++owners[k];
                ++sizes[static_cast<std::size_t>(index - 1)];
            }
        }
    }
    CHECK(owners == std::vector<int>(10, 1));
    CHECK(sizes == std::vector<int>{4, 3, 3});
    CHECK(Shard{1, 3}.holds(0));
    CHECK(Shard{1, 3}.holds(3));
    CHECK(Shard{2, 3}.holds(1));
}
