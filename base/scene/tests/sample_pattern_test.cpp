#include "base/scene/sample_pattern.h"

#include "base/testing/catch.h"

using namespace raystep;

TEST_CASE("fills_square_grid: n x n samples fill a grid, their neighbours do not", "[scene]") {
    for (const int side : {1, 2, 3, 16, 256}) {
        CHECK(fills_square_grid(side * side));
        CHECK_FALSE(fills_square_grid(side * side + 1));
        if (side > 1) CHECK_FALSE(fills_square_grid(side * side - 1));
    }
    CHECK_FALSE(fills_square_grid(2));
    CHECK_FALSE(fills_square_grid(0));
    CHECK_FALSE(fills_square_grid(-4));
}

TEST_CASE("sample_pattern_name: each pattern's name reads back as the pattern", "[scene]") {
    for (const SamplePattern pattern :
         {SamplePattern::jittered, SamplePattern::regular, SamplePattern::random}) {
        CHECK(parse_sample_pattern(sample_pattern_name(pattern)) == pattern);
    }
    CHECK_FALSE(parse_sample_pattern("stratified").has_value());
}
