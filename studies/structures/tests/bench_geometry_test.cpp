#include "studies/structures/bench_geometry.h"

#include <glm/geometric.hpp>

#include "base/testing/catch.h"
#include "studies/structures/bumpy_torus.h"

using namespace raystep;

TEST_CASE("random_spheres: seeded, in the unit cube, radii a fraction of the spacing", "[bench]") {
    const std::vector<Sphere> a = random_spheres(1000, 2026);
    const std::vector<Sphere> b = random_spheres(1000, 2026);
    REQUIRE(a.size() == 1000);
    for (std::size_t k = 0; k < a.size(); ++k) {
        CAPTURE(k);
        REQUIRE(a[k].center == b[k].center);
        REQUIRE(a[k].radius == b[k].radius);
        REQUIRE(glm::all(glm::greaterThanEqual(a[k].center, Vec3(0.0))));
        REQUIRE(glm::all(glm::lessThan(a[k].center, Vec3(1.0))));
        // Spacing 1000^(-1/3) = 0.1
        REQUIRE(a[k].radius >= 0.025 - 1e-12);
        REQUIRE(a[k].radius < 0.075 + 1e-12);
    }
    CHECK(random_spheres(1000, 2027)[0].center != a[0].center);
}

TEST_CASE("random_triangles: seeded, each within a cube of side n^(-1/3)", "[bench]") {
    const std::vector<Triangle> a = random_triangles(64, 512);
    const std::vector<Triangle> b = random_triangles(64, 512);
    REQUIRE(a.size() == 64);
    for (std::size_t k = 0; k < a.size(); ++k) {
        CAPTURE(k);
        REQUIRE(a[k].p0 == b[k].p0);
        REQUIRE(a[k].p2 == b[k].p2);
        // Two vertices within the same cube of side 1/4 differ by less than 1/4 per axis
        REQUIRE(glm::all(glm::lessThan(glm::abs(a[k].p1 - a[k].p0), Vec3(0.25))));
    }
}

TEST_CASE("mesh_triangles and tiled_copies: faces in order, copies shifted by the extent",
          "[bench]") {
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 4}};
    mesh.faces = {{0, 1, 2}, {0, 2, 3}};
    const std::vector<Triangle> triangles = mesh_triangles(mesh);
    REQUIRE(triangles.size() == 2);
    CHECK(triangles[1].p2 == Vec3(0, 0, 4));

    // Extent (2, 1, 4), spacing 1.5: copies step 3 along x and 6 along z
    const std::vector<Triangle> copies = tiled_copies(triangles, 4, 4, 1.5);
    REQUIRE(copies.size() == 32);
    CHECK(copies[0].p1 == Vec3(2, 0, 0));
    CHECK(copies[2].p1 == Vec3(5, 0, 0));    // column 1
    CHECK(copies[8].p1 == Vec3(2, 0, 6));    // row 1
    CHECK(copies[31].p2 == Vec3(9, 0, 22));  // column 3, row 3
}

TEST_CASE("bumpy_torus: 2 rings segments triangles, none degenerate, around the y axis",
          "[bench]") {
    const std::vector<Triangle> torus = bumpy_torus(16, 32);
    REQUIRE(torus.size() == 1024);
    for (std::size_t k = 0; k < torus.size(); ++k) {
        const Triangle& t = torus[k];
        CAPTURE(k);
        REQUIRE(glm::length(glm::cross(t.p1 - t.p0, t.p2 - t.p0)) > 0.0);
        // Within the tube's largest radius, 0.3 * 1.35, of the circle of radius 1 in y = 0
        const double from_axis = std::hypot(t.p0.x, t.p0.z);
        REQUIRE(std::hypot(from_axis - 1.0, t.p0.y) <= 0.3 * 1.35 + 1e-12);
    }
    // The same surface sampled more finely: the larger torus's first vertex is the smaller's
    CHECK(bumpy_torus(32, 64)[0].p0 == torus[0].p0);
}
