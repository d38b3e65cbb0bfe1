// Public tests for stage 2, rays. Run them with `ctest --test-dir build/release -L stage2`.

#include "stages/2_rays/ray.h"
#include "base/testing/catch.h"

using namespace raystep;

TEST_CASE("Ray::at: t = 0 is the origin", "[stage2]") {
    const Ray ray{{1, 2, 3}, {0, 0, -1}};
    CHECK(ray.at(0.0) == Vec3(1, 2, 3));
}

TEST_CASE("Ray::at: walks t times the direction", "[stage2]") {
    const Ray ray{{1, 2, 3}, {0.5, 0, -2}};
    CHECK(ray.at(2.0) == Vec3(2, 2, -1));
    CHECK(ray.at(-1.0) == Vec3(0.5, 2, 5));
}

TEST_CASE("Ray::at: with a unit direction, t is the distance from the origin", "[stage2]") {
    const Ray ray{{0, 0, 0}, {0.6, 0.8, 0}};
    CHECK(ray.at(5.0).x == Approx(3.0));
    CHECK(ray.at(5.0).y == Approx(4.0));
}
