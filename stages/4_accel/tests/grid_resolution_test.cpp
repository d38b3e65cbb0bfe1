// Public tests for stage 4, the grid's resolution. Run them with
// `build/student/bin/raystep_stage4_tests "grid_resolution:*"`.
//
// Each check calls grid_resolution before its CHECKs: a stub ends the test case at its first call
// and is reported once. A failure prints the box and the number of primitives, and ends the test
// case.

#include <cstddef>
#include <limits>

#include "base/testing/catch.h"
#include "base/testing/number_text.h"
#include "base/testing/vec3_matchers.h"
#include "stages/4_accel/uniform_grid.h"

using namespace raystep;

namespace {

// grid_resolution(box, count) against `expected`, with the inputs in the failure message; a wrong
// answer ends the test case.
void check_resolution(const Aabb& box, std::size_t count, const glm::ivec3& expected) {
    using raystep::testing::exact_text;
    INFO("box: min " << exact_text(box.min) << ", max " << exact_text(box.max) << ", " << count
                     << " primitives");
    const glm::ivec3 got = grid_resolution(box, count);
    INFO("got " << got.x << " x " << got.y << " x " << got.z << " cells, expected " << expected.x
                << " x " << expected.y << " x " << expected.z);
    REQUIRE(got.x == expected.x);
    REQUIRE(got.y == expected.y);
    REQUIRE(got.z == expected.z);
}

}  // namespace

TEST_CASE("grid_resolution: a cube with 9 primitives gets 3 x 3 x 3 cells", "[stage4]") {
    INFO(
        "3 cells per primitive, 27 in all: 3 per axis. Where the cube is and how big does not "
        "matter.");
    check_resolution({{0, 0, 0}, {1, 1, 1}}, 9, {3, 3, 3});
    check_resolution({{2, 2, 2}, {4, 4, 4}}, 9, {3, 3, 3});
    check_resolution({{-1e6, -1e6, -1e6}, {-0.5e6, -0.5e6, -0.5e6}}, 9, {3, 3, 3});
}

TEST_CASE(
    "grid_resolution: a long box gets cells in proportion, as near cubes as whole numbers allow",
    "[stage4]") {
    INFO("4 x 1 x 1, 12 primitives: k = cbrt(36 / 4) = 2.08 cells per unit, so 8.3 x 2.08 x 2.08.");
    check_resolution({{0, 0, 0}, {4, 1, 1}}, 12, {8, 2, 2});
    // 1 x 2 x 3, 16 primitives: k = cbrt(48 / 6) = 2 exactly.
    check_resolution({{0, 0, 0}, {1, 2, 3}}, 16, {2, 4, 6});
}

TEST_CASE("grid_resolution: a flat box shares the cells among its long axes", "[stage4]") {
    INFO("4 x 4 x 0, 12 primitives: 36 cells over the area, k = sqrt(36 / 16) = 1.5: 6 x 6 x 1.");
    check_resolution({{0, 0, 0}, {4, 4, 0}}, 12, {6, 6, 1});
    check_resolution({{0, 0, 0}, {4, 0, 4}}, 12, {6, 1, 6});
    // Nearly flat is flat: z is far too thin for a whole cell, so x and y share the 36. The cube
    // formula alone would give k = cbrt(36 / 16e-9) = 1.3e3 and 256 x 256 x 1 cells.
    check_resolution({{0, 0, 0}, {4, 4, 1e-9}}, 12, {6, 6, 1});
    // A line: all 9 cells along it.
    check_resolution({{0, 0, 0}, {4, 0, 0}}, 3, {9, 1, 1});
    // 4 x 4 x 0.1 with 12: z would get 0.28 of a cell, so it is flat too.
    check_resolution({{0, 0, 0}, {4, 4, 0.1}}, 12, {6, 6, 1});
}

TEST_CASE("grid_resolution: no primitives, one primitive, a point or an empty box get one cell",
          "[stage4]") {
    check_resolution({{0, 0, 0}, {1, 1, 1}}, 0, {1, 1, 1});
    check_resolution({{0, 0, 0}, {1, 1, 1}}, 1, {1, 1, 1});  // cbrt(3) = 1.44
    check_resolution({{1, 2, 3}, {1, 2, 3}}, 5, {1, 1, 1});
    check_resolution(Aabb{}, 5, {1, 1, 1});
}

TEST_CASE("grid_resolution: at most 256 cells along an axis, however many primitives", "[stage4]") {
    check_resolution({{0, 0, 0}, {1, 1, 1}}, 10'000'000, {256, 256, 256});
    check_resolution({{0, 0, 0}, {1, 1, 1}}, std::numeric_limits<std::size_t>::max(),
                     {256, 256, 256});
    // 1000 x 1 x 1 with a million: k = cbrt(3e6 / 1000) = 14.4; x is capped, y and z are not.
    check_resolution({{0, 0, 0}, {1000, 1, 1}}, 1'000'000, {256, 14, 14});
}
