#include "core/scene/mesh_loader.h"

#include <filesystem>
#include <string>

#include "core/errors/input_error.h"
#include "core/testing/catch.h"

using namespace raystep;

namespace {

const std::filesystem::path kMeshes = std::filesystem::path(RAYSTEP_TEST_DATA) / "meshes";

void check_unit_square(const TriangleMesh& mesh) {
    REQUIRE(mesh.positions.size() == 4);
    CHECK(mesh.positions[2] == Vec3(1, 1, 0));
    REQUIRE(mesh.faces.size() == 2);  // the quad 0 1 2 3 fans into 0 1 2 and 0 2 3
    CHECK(mesh.faces[0] == std::array<std::uint32_t, 3>{0, 1, 2});
    CHECK(mesh.faces[1] == std::array<std::uint32_t, 3>{0, 2, 3});
}

std::string error_of(const std::filesystem::path& path) {
    try {
        load_mesh(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST_CASE("load_mesh: OFF with a comment, a quad face and a face colour", "[core]") {
    check_unit_square(load_mesh(kMeshes / "square.off"));
}

TEST_CASE("load_mesh: OBJ with a quad face, 1-based indices", "[core]") {
    check_unit_square(load_mesh(kMeshes / "square.obj"));
}

TEST_CASE("load_mesh: OFF errors name the file and the line", "[core]") {
    const std::string bad_index = (kMeshes / "bad_index.off").string();
    CHECK(error_of(kMeshes / "bad_index.off") ==
          bad_index +
              ":6: vertex index 3 is out of range: the file has 3 vertices, numbered from 0");
    CHECK_THAT(
        error_of(kMeshes / "bad_header.off"),
        Catch::Matchers::Contains("bad_header.off:1: expected 'OFF' at the start, found 'OFX'"));
    CHECK_THAT(
        error_of(kMeshes / "truncated.off"),
        Catch::Matchers::Contains("truncated.off:4: the file ends before a vertex coordinate"));
    CHECK_THAT(
        error_of(kMeshes / "non_finite.off"),
        Catch::Matchers::Contains("non_finite.off:4: a vertex coordinate 'inf' is not finite"));
}

TEST_CASE("load_mesh: OBJ errors name the file", "[core]") {
    CHECK_THAT(error_of(kMeshes / "bad_index.obj"),
               Catch::Matchers::Contains("bad_index.obj") &&
                   (Catch::Matchers::Contains("vertex 4") || Catch::Matchers::Contains("index")));
}

TEST_CASE("load_mesh: an unknown extension or a missing file is an error", "[core]") {
    CHECK_THAT(error_of(kMeshes / "cube.ply"),
               Catch::Matchers::Contains("unknown mesh format '.ply'"));
    CHECK_THAT(error_of(kMeshes / "missing.off"), Catch::Matchers::Contains("missing.off"));
    CHECK_THAT(error_of(kMeshes / "missing.obj"), Catch::Matchers::Contains("missing.obj"));
}
