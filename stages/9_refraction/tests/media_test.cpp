// Public tests for stage 9, entering and leaving solids. Run them with
// `ctest --preset student -L stage9`, one function's with
// `build/student/bin/raystep_stage9_tests "after_crossing:*"`.
//
// A ray's media are a stack of the solids it is inside, in the order it entered them. The cases
// follow one ray through air, a glass holding water holding an ice cube, and two overlapping
// solids. Each test calls your function before its CHECKs: a stub is reported once. A test of
// several crossings stops at the first that fails.

#include <string>

#include "base/testing/catch.h"
#include "stages/9_refraction/refraction.h"

using namespace raystep;

namespace {

const Medium kGlass{1, 1.5};
const Medium kWater{2, 1.33};
const Medium kIce{3, 1.31};

std::string text(const MediumStack& stack) {
    std::string out = "[";
    for (const Medium& medium : stack)
        out += (out.size() > 1 ? ", " : "") + std::string("solid ") + std::to_string(medium.solid) +
               " index " + std::to_string(medium.index);
    return out + "]";
}

// after_crossing, with the stacks in the failure message; a wrong stack ends the test case.
void check_crossing(const MediumStack& before, const Medium& solid, bool entering,
                    const MediumStack& expected) {
    INFO("before " << text(before) << (entering ? ", entering" : ", leaving") << " solid "
                   << solid.solid);
    const MediumStack after = after_crossing(before, solid, entering);
    INFO("after " << text(after) << ", expected " << text(expected));
    REQUIRE(after == expected);
}

}  // namespace

TEST_CASE("current_index: 1 in air, the empty stack", "[stage9]") {
    CHECK(current_index({}) == 1.0);
}

TEST_CASE("current_index: the index of the last solid entered", "[stage9]") {
    INFO("In water inside a glass, the ray travels in water: 1.33, not the glass's 1.5.");
    const double in_water = current_index({kGlass, kWater});
    const double in_glass = current_index({kWater, kGlass});
    CHECK(in_water == 1.33);
    CHECK(in_glass == 1.5);
}

TEST_CASE("after_crossing: entering a solid from air puts it on the stack", "[stage9]") {
    check_crossing({}, kGlass, true, {kGlass});
}

TEST_CASE("after_crossing: nested solids are left in the reverse order", "[stage9]") {
    INFO("Into a glass, into its water, into the ice cube in it, then out of each.");
    check_crossing({kGlass}, kWater, true, {kGlass, kWater});
    check_crossing({kGlass, kWater}, kIce, true, {kGlass, kWater, kIce});
    check_crossing({kGlass, kWater, kIce}, kIce, false, {kGlass, kWater});
    check_crossing({kGlass, kWater}, kWater, false, {kGlass});
    check_crossing({kGlass}, kGlass, false, {});
}

TEST_CASE("after_crossing: overlapping solids may be left in the order they were entered",
          "[stage9]") {
    INFO(
        "Two solids that overlap: the ray enters the glass, then the water, then leaves the glass "
        "first. It is then in water alone, not in glass.");
    check_crossing({kGlass, kWater}, kGlass, false, {kWater});
}

TEST_CASE("after_crossing: leaving a solid never entered changes nothing", "[stage9]") {
    INFO(
        "A ray that starts inside a solid (a camera under water) leaves it without having entered "
        "it: the stack stays as it was, and the medium beyond is the current one.");
    check_crossing({}, kWater, false, {});
    check_crossing({kGlass}, kWater, false, {kGlass});
}
