#include "studies/epsilon/exact_visibility.h"

#include <string>

#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"

using namespace raystep;

namespace {

Scene parse(const std::string& text) {
    return parse_scene("camera 0 0 5 0 0 0 0 1 0 45\n" + text, "exact.test", ".");
}

const Vec3 kDown{0, 0, -1};

}  // namespace

TEST_CASE("exact_first_hit: the nearest primitive along the ray", "[bench]") {
    const Scene scene = parse("sphere 0 0 -3 1\nsphere 0 0 0 1\nplane 0 0 -10 0 0 1\n");
    const ExactHit hit = exact_first_hit(scene, {0, 0, 5}, kDown);
    REQUIRE(hit.decided);
    REQUIRE(hit.primitive);
    CHECK(hit.primitive->kind == PrimitiveRef::Kind::sphere);
    CHECK(hit.primitive->index == 1);
    CHECK(hit.t == Approx(4.0));
}

TEST_CASE("exact_first_hit: a miss is decided and has no primitive", "[bench]") {
    const ExactHit hit = exact_first_hit(parse("sphere 5 0 0 1\n"), {0, 0, 5}, kDown);
    CHECK(hit.decided);
    CHECK_FALSE(hit.primitive);
}

TEST_CASE("exact_first_hit: a silhouette within 1e-12 is undecided, farther is not", "[bench]") {
    // The ray x = 1 + delta grazes the unit sphere's silhouette.
    const Scene scene = parse("sphere 0 0 0 1\n");
    CHECK_FALSE(exact_first_hit(scene, {1.0 + 1e-15, 0, 5}, kDown).decided);
    CHECK(exact_first_hit(scene, {1.0 + 1e-6, 0, 5}, kDown).decided);
    CHECK(exact_first_hit(scene, {1.0 - 1e-6, 0, 5}, kDown).primitive);
}

TEST_CASE("exact_first_hit: a triangle's edge and a tie are undecided", "[bench]") {
    const Scene triangle = parse("vertex -1 -1 0\nvertex 1 -1 0\nvertex 0 1 0\ntri 0 1 2\n");
    CHECK_FALSE(exact_first_hit(triangle, {0, -1, 5}, kDown).decided);  // on the edge y = -1
    CHECK(exact_first_hit(triangle, {0, -0.9, 5}, kDown).primitive);
    const Scene tie = parse("plane 0 0 0 0 0 1\nplane 0 0 0 0 0 2\n");
    CHECK_FALSE(exact_first_hit(tie, {0, 0, 5}, kDown).decided);
}

TEST_CASE("exact_light_reaches: a clear path, a blocker, and a light behind the surface",
          "[bench]") {
    const Scene floor = parse("plane 0 0 0 0 0 1\nsphere 5 0 1 0.5\n");
    const ExactHit hit = exact_first_hit(floor, {0, 0, 5}, kDown);
    REQUIRE(hit.primitive);
    CHECK(exact_light_reaches(floor, {0, 0, 5}, kDown, hit, {0, 0, 3}) == Decided::yes);
    CHECK(exact_light_reaches(floor, {0, 0, 5}, kDown, hit, {10, 0, 2}) == Decided::no);
    CHECK(exact_light_reaches(floor, {0, 0, 5}, kDown, hit, {0, 0, -3}) == Decided::no);
    // A light just above the floor, grazing, still reaches: the floor does not shadow itself.
    CHECK(exact_light_reaches(floor, {0, 0, 5}, kDown, hit, {-100, 0, 1e-3}) == Decided::yes);
}

TEST_CASE("exact_light_reaches: what lies beyond the light does not block it", "[bench]") {
    // The eye ray meets the floor at (3, 0, 0); the light is 2 above it and the sphere 4 above,
    // on the same vertical: past the light, out of the segment.
    const Scene scene = parse("plane 0 0 0 0 0 1\nsphere 3 0 4 0.5\n");
    const Vec3 towards_floor{3, 0, -5};
    const ExactHit hit = exact_first_hit(scene, {0, 0, 5}, towards_floor);
    REQUIRE(hit.primitive);
    REQUIRE(hit.primitive->kind == PrimitiveRef::Kind::plane);
    CHECK(exact_light_reaches(scene, {0, 0, 5}, towards_floor, hit, {3, 0, 2}) == Decided::yes);
    CHECK(exact_light_reaches(scene, {0, 0, 5}, towards_floor, hit, {3, 0, 6}) == Decided::no);
}

TEST_CASE("exact_light_reaches: a sphere lights only the half that faces the light", "[bench]") {
    const Scene scene = parse("sphere 0 0 0 1\n");
    const ExactHit top = exact_first_hit(scene, {0, 0, 5}, kDown);
    CHECK(exact_light_reaches(scene, {0, 0, 5}, kDown, top, {0, 0, 10}) == Decided::yes);
    CHECK(exact_light_reaches(scene, {0, 0, 5}, kDown, top, {0, 0, -10}) == Decided::no);
    // A light in the tangent plane at the top, within 1e-12: undecided.
    CHECK(exact_light_reaches(scene, {0, 0, 5}, kDown, top, {10, 0, 1}) == Decided::undecided);
}
