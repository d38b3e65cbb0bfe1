#include "base/scene/mesh_loader.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "base/errors/input_error.h"
#include "base/testing/catch.h"

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

TEST_CASE("load_mesh: OFF with a comment, a quad face and a face colour", "[base]") {
    check_unit_square(load_mesh(kMeshes / "square.off"));
}

TEST_CASE("load_mesh: OBJ with a quad face, 1-based indices", "[base]") {
    check_unit_square(load_mesh(kMeshes / "square.obj"));
}

TEST_CASE("load_mesh: OBJ negative indices count back from the last vertex", "[base]") {
    const TriangleMesh mesh = load_mesh(kMeshes / "relative_indices.obj");
    REQUIRE(mesh.faces.size() == 1);
    CHECK(mesh.faces[0] == std::array<std::uint32_t, 3>{0, 1, 2});
}

TEST_CASE("load_mesh: OFF errors name the file and the line", "[base]") {
    const std::string bad_index = (kMeshes / "bad_index.off").string();
    CHECK(error_of(kMeshes / "bad_index.off") ==
          bad_index +
              ":6: vertex index 3 is out of range: the file has 3 vertices, numbered from 0");
    CHECK_THAT(
        error_of(kMeshes / "bad_header.off"),
        Catch::Matchers::Contains("bad_header.off:1: expected 'OFF' at the start, found 'OFX'"));
    CHECK_THAT(error_of(kMeshes / "truncated.off"),
               Catch::Matchers::Contains("truncated.off:5: the file ends before vertex 2 of 3"));
    CHECK_THAT(
        error_of(kMeshes / "non_finite.off"),
        Catch::Matchers::Contains("non_finite.off:4: a vertex coordinate 'inf' is not finite"));
}

TEST_CASE("load_mesh: an OFF record is one line and never borrows from the next", "[base]") {
    CHECK_THAT(error_of(kMeshes / "short_face.off"),
               Catch::Matchers::Contains("short_face.off:6: a face of 3 vertices lists only 2"));
    CHECK_THAT(
        error_of(kMeshes / "short_vertex.off"),
        Catch::Matchers::Contains("short_vertex.off:3: a vertex needs 3 numbers, this line has 2"));
}

TEST_CASE("load_mesh: an OFF header promising more than the file holds allocates nothing",
          "[base]") {
    CHECK_THAT(
        error_of(kMeshes / "huge_header.off"),
        Catch::Matchers::Contains("huge_header.off:2: the header promises 999999999999 vertices"));
}

TEST_CASE("load_mesh: OBJ errors name the file and the line", "[base]") {
    CHECK_THAT(error_of(kMeshes / "bad_index.obj"),
               Catch::Matchers::Contains(
                   "bad_index.obj:4: vertex index 4 is out of range: the file has 3 vertices"));
    CHECK_THAT(error_of(kMeshes / "bad_coordinate.obj"),
               Catch::Matchers::Contains(
                   "bad_coordinate.obj:2: a vertex coordinate 'abc' is not a number"));
    CHECK_THAT(error_of(kMeshes / "short_face.obj"),
               Catch::Matchers::Contains(
                   "short_face.obj:4: a face needs 3 to 255 vertices, this one has 2"));
    CHECK_THAT(
        error_of(kMeshes / "huge_index.obj"),
        Catch::Matchers::Contains("huge_index.obj:4: vertex index 99999999999 is out of range"));
    CHECK_THAT(
        error_of(kMeshes / "bad_relative_index.obj"),
        Catch::Matchers::Contains("bad_relative_index.obj:4: vertex index -4 is out of range"));
}

TEST_CASE("load_mesh: OBJ vertex normals, fanned with their face, as written", "[base]") {
    const TriangleMesh mesh = load_mesh(kMeshes / "normals.obj");
    REQUIRE(mesh.normals.size() == 3);
    CHECK(mesh.normals[1] == Vec3(0, 0, 2));  // not normalized: the renderer decides
    REQUIRE(mesh.faces.size() == 3);
    REQUIRE(mesh.face_normals.size() == 3);
    // The quad's corners 1//1 2//2 3//3 4//1 fan as its positions do.
    CHECK(mesh.face_normals[0] == std::array<std::uint32_t, 3>{0, 1, 2});
    CHECK(mesh.face_normals[1] == std::array<std::uint32_t, 3>{0, 2, 0});
    // A face with a corner that names no normal has none.
    CHECK(mesh.face_normals[2] == std::array<std::uint32_t, 3>{kNoCorner, kNoCorner, kNoCorner});
}

TEST_CASE("load_mesh: OBJ texture coordinates, fanned with their face", "[base]") {
    const TriangleMesh mesh = load_mesh(kMeshes / "uvs.obj");
    REQUIRE(mesh.uvs.size() == 4);
    CHECK(mesh.uvs[2] == Vec2(1, 1));
    REQUIRE(mesh.face_uvs.size() == 2);
    CHECK(mesh.face_uvs[1] == std::array<std::uint32_t, 3>{0, 2, 3});
    CHECK(mesh.face_normals[1] == std::array<std::uint32_t, 3>{0, 0, 0});
    CHECK_THAT(error_of(kMeshes / "bad_uv_index.obj"),
               Catch::Matchers::Contains("bad_uv_index.obj:5: texture coordinate index 2 is out "
                                         "of range: the file has 1 texture coordinates"));
}

TEST_CASE("load_mesh: OBJ materials from its MTL library, each face's by usemtl", "[base]") {
    const TriangleMesh mesh = load_mesh(kMeshes / "materials.obj");
    REQUIRE(mesh.materials.size() == 3);
    const MeshMaterial& painted = mesh.materials[0];
    CHECK(painted.name == "painted");
    // Approx: a build with tinyobjloader's float reader rounds the file's numbers to float.
    CHECK(painted.diffuse.r == Approx(0.8));
    CHECK(painted.diffuse.b == Approx(0.1));
    CHECK(painted.diffuse_map.file == kMeshes / "maps/two.ppm");
    CHECK(painted.diffuse_map.wrap == WrapMode::clamp);  // -clamp on
    CHECK(painted.bump_map.file.empty());
    const MeshMaterial& bricks = mesh.materials[1];
    CHECK(bricks.bump_map.file == kMeshes / "maps/two.ppm");
    CHECK(bricks.bump_map.wrap == WrapMode::repeat);
    CHECK(bricks.bump_scale == Approx(0.05));  // -bm
    CHECK(bricks.normal_map.file == kMeshes / "maps/two.ppm");
    CHECK(mesh.materials[2].bump_map.file == kMeshes / "maps/two.ppm");  // `bump`, map_Bump's twin
    CHECK(mesh.materials[2].bump_scale == Approx(0.05));
    // The triangle before any usemtl has none; each quad's two triangles have its material.
    CHECK(mesh.face_materials == std::vector<std::int32_t>{-1, 0, 0, 1, 1, 2});
    CHECK(load_mesh(kMeshes / "square.obj").materials.empty());
    CHECK(load_mesh(kMeshes / "square.obj").face_materials.empty());
}

TEST_CASE("load_mesh: a missing material library, material or map names the file and line",
          "[base]") {
    CHECK_THAT(error_of(kMeshes / "missing_library.obj"),
               Catch::Matchers::Contains("missing_library.obj:2: material library 'nowhere.mtl' "
                                         "not found"));
    CHECK_THAT(error_of(kMeshes / "missing_map.obj"),
               Catch::Matchers::Contains("missing_map.obj:5: material 'lost': its map_Kd image "
                                         "'none.png' not found"));
}

TEST_CASE("load_mesh: a usemtl the reader cannot give its faces is an error at its line",
          "[base]") {
    // tinyobjloader knows a material only from a library named above the usemtl, and would leave
    // the faces in the material in force.
    for (const char* file :
         {"unknown_material.obj", "material_without_library.obj", "material_before_library.obj"}) {
        CAPTURE(file);
        CHECK_THAT(error_of(kMeshes / file),
                   Catch::Matchers::Contains(std::string(file) + ":") &&
                       Catch::Matchers::Contains("is in no material library named above this "
                                                 "line"));
    }
    CHECK_THAT(error_of(kMeshes / "unknown_material.obj"),
               Catch::Matchers::Contains("unknown_material.obj:5: material 'stone'"));
    CHECK_THAT(error_of(kMeshes / "library_in_folder.obj"),
               Catch::Matchers::Contains("library_in_folder.obj:1: material library "
                                         "'../meshes/materials.mtl' is not a file name"));
    CHECK_THAT(error_of(kMeshes / "face_of_256.obj"),
               Catch::Matchers::Contains("face_of_256.obj:257: a face needs 3 to 255 vertices, "
                                         "this one has 256"));
}

TEST_CASE("load_mesh: a file without normals has none", "[base]") {
    const TriangleMesh mesh = load_mesh(kMeshes / "square.obj");
    CHECK(mesh.normals.empty());
    CHECK(mesh.face_normals.empty());
}

TEST_CASE("load_mesh: OBJ normal errors name the file and the line", "[base]") {
    CHECK_THAT(error_of(kMeshes / "bad_normal_index.obj"),
               Catch::Matchers::Contains("bad_normal_index.obj:5: vertex normal index 2 is out of "
                                         "range: the file has 1 vertex normals"));
    CHECK_THAT(error_of(kMeshes / "zero_normal.obj"),
               Catch::Matchers::Contains("zero_normal.obj:4: a vertex normal is zero"));
}

TEST_CASE("area_weighted_normals: each vertex sums its faces' normals, weighted by area",
          "[base]") {
    // Two triangles meeting at the edge 0-1: one in the plane z = 0 of area 1/2, one in the
    // plane y = 0 of area 2, facing +y.
    TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 2}};
    mesh.faces = {{0, 1, 2}, {0, 3, 1}};
    const std::vector<Vec3> normals = area_weighted_normals(mesh);
    REQUIRE(normals.size() == 4);
    CHECK(normals[2] == Vec3(0, 0, 1));  // the first face's (p1 - p0) x (p2 - p0)
    CHECK(normals[3] == Vec3(0, 2, 0));  // the second's, four times as large
    CHECK(normals[0] == Vec3(0, 2, 1));  // both: the larger face weighs more
    CHECK(normals[1] == normals[0]);
}

TEST_CASE("load_mesh: an unknown extension, a missing file or a folder is an error", "[base]") {
    CHECK_THAT(error_of(kMeshes / "cube.ply"),
               Catch::Matchers::Contains("unknown mesh format '.ply'"));
    CHECK_THAT(error_of(kMeshes / "missing.off"),
               Catch::Matchers::Contains("missing.off: not a regular file"));
    CHECK_THAT(error_of(kMeshes), Catch::Matchers::Contains("not a regular file"));
}
