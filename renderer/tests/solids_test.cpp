#include "renderer/solids.h"

#include <filesystem>
#include <fstream>

#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"

using namespace raystep;

TEST_CASE("solid_of: spheres apart, loose triangles by material, each mesh instance apart",
          "[app]") {
    // Two spheres, four loose triangles under two materials, one mesh defined and placed twice,
    // and a plane.
    const std::filesystem::path folder = std::filesystem::temp_directory_path();
    const std::filesystem::path mesh = folder / "solids_test_triangle.obj";
    std::ofstream(mesh) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const Scene scene = parse_scene(
        "size 4 4\ncamera 0 0 5 0 0 0 0 1 0 45\nsphere 0 0 0 1\nsphere 3 0 0 1\n"
        "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\ndiffuse 1 0 0\ntri 0 1 2\ntri 0 2 1\n"
        "diffuse 0 1 0\ntri 0 1 2\ntri 0 2 1\ndefine piece solids_test_triangle.obj\n"
        "instance piece\ntranslate 5 0 0\ninstance piece\nplane 0 -1 0 0 1 0\n",
        "solids.test", folder);
    const RenderScene render_scene = prepare_render_scene(scene);
    const std::uint32_t sphere0 = solid_of(render_scene, PrimitiveKind::sphere, 0);
    const std::uint32_t sphere1 = solid_of(render_scene, PrimitiveKind::sphere, 1);
    CHECK(sphere0 != sphere1);
    const std::uint32_t red0 = solid_of(render_scene, PrimitiveKind::triangle, 0);
    CHECK(solid_of(render_scene, PrimitiveKind::triangle, 1) == red0);
    const std::uint32_t green = solid_of(render_scene, PrimitiveKind::triangle, 2);
    CHECK(solid_of(render_scene, PrimitiveKind::triangle, 3) == green);
    CHECK(green != red0);
    // The two placements: triangles 4 and 5 of the scene's numbering
    const std::uint32_t first = solid_of(render_scene, PrimitiveKind::triangle, 4);
    const std::uint32_t second = solid_of(render_scene, PrimitiveKind::triangle, 5);
    CHECK(first != second);
    const std::uint32_t plane = solid_of(render_scene, PrimitiveKind::plane, 0);
    for (std::uint32_t other : {sphere0, sphere1, red0, green, first, second}) {
        CHECK(other != plane);
    }
    CHECK(first != sphere0);
    CHECK(first != sphere1);
    CHECK(first != red0);
    CHECK(first != green);
    std::filesystem::remove(mesh);
}
