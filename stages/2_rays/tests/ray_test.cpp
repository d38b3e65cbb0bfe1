// Public tests for stage 2, rays. Run them with `ctest --preset student -L stage2`, Ray::at's
// alone with `build/student/bin/raystep_stage2_tests "Ray::at:*"`. A failure prints the ray.

#include <string>

#include "base/testing/catch.h"
#include "base/testing/number_text.h"
#include "stages/2_rays/ray.h"

using namespace raystep;

namespace {

std::string text(const Ray& ray) {
    using raystep::testing::exact_text;
    return "ray: origin " + exact_text(ray.origin) + ", direction " + exact_text(ray.direction);
}

}  // namespace

TEST_CASE("Ray::at: t = 0 is the origin", "[stage2]") {
    const Ray ray{{1, 2, 3}, {0, 0, -1}};
    INFO(text(ray));
    CHECK(ray.at(0.0) == Vec3(1, 2, 3));
}

TEST_CASE("Ray::at: walks t times the direction", "[stage2]") {
    const Ray ray{{1, 2, 3}, {0.5, 0, -2}};
    INFO(text(ray));
    const Vec3 ahead = ray.at(2.0);
    const Vec3 behind = ray.at(-1.0);
    CHECK(ahead == Vec3(2, 2, -1));
    CHECK(behind == Vec3(0.5, 2, 5));
}

TEST_CASE("Ray::at: with a unit direction, t is the distance from the origin", "[stage2]") {
    const Ray ray{{0, 0, 0}, {0.6, 0.8, 0}};
    INFO(text(ray));
    const Vec3 at_5 = ray.at(5.0);
    CHECK(at_5.x == Approx(3.0));
    CHECK(at_5.y == Approx(4.0));
}
