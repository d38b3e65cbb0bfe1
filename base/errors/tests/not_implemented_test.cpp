#include "base/errors/not_implemented.h"

#include "base/errors/input_error.h"
#include "base/testing/catch.h"

using namespace raystep;

namespace {

double stub() {
    RAYSTEP_TODO(3, "intersect_sphere", "Ray-sphere");
}

}  // namespace

TEST_CASE("RAYSTEP_TODO: names the stage, the function and the handout section", "[base]") {
    try {
        stub();
        FAIL("the stub returned");
    } catch (const NotImplemented& e) {
        CHECK(std::string(e.what()) ==
              "stage 3: intersect_sphere is not implemented yet, see docs/stage3.md, section "
              "\"Ray-sphere\"");
        CHECK(e.stage() == 3);
        CHECK(e.function() == "intersect_sphere");
        CHECK(e.section() == "Ray-sphere");
    }
}

TEST_CASE("InputError: reads file:line: problem, or file: problem without a line", "[base]") {
    CHECK(std::string(InputError("a.test", 12, "bad").what()) == "a.test:12: bad");
    CHECK(std::string(InputError("a.test", 0, "bad").what()) == "a.test: bad");
}
