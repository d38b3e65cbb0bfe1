#include "base/scene/scene_loader.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "base/errors/input_error.h"
#include "base/scene/scene_features.h"
#include "base/testing/catch.h"

using namespace raystep;

namespace {

const std::filesystem::path kData = RAYSTEP_TEST_DATA;

Scene parse(const std::string& text) {
    return parse_scene(text, "inline.test", kData);
}

const std::string kCamera = "camera 0 0 5 0 0 0 0 1 0 45\n";

// The first line of every bad scene says what the loader must report:
// "# expect: LINE: TEXT", LINE 0 meaning the file as a whole.
struct Expectation {
    int line;
    std::string text;
};

Expectation read_expectation(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::string first;
    std::getline(in, first);
    const std::string prefix = "# expect: ";
    REQUIRE(first.rfind(prefix, 0) == 0);
    const std::string rest = first.substr(prefix.size());
    const std::size_t colon = rest.find(": ");
    REQUIRE(colon != std::string::npos);
    return {std::stoi(rest.substr(0, colon)), rest.substr(colon + 2)};
}

}  // namespace

TEST_CASE("load_scene: every bad scene is reported as file:line: problem", "[base]") {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kData / "bad_scenes")) {
        ++files;
        const std::filesystem::path file = entry.path();
        CAPTURE(file.filename().string());
        const Expectation expected = read_expectation(file);
        try {
            load_scene(file);
            FAIL("the scene loaded without an error");
        } catch (const InputError& error) {
            CHECK(error.file() == file.string());
            CHECK(error.line() == expected.line);
            const std::string location =
                expected.line > 0 ? file.string() + ":" + std::to_string(expected.line) + ": "
                                  : file.string() + ": ";
            CHECK(std::string(error.what()).rfind(location, 0) == 0);
            CHECK_THAT(error.problem(), Catch::Matchers::Contains(expected.text));
        }
    }
    CHECK(files >= 30);  // the corpus is there: this loop cannot pass by testing nothing
}

TEST_CASE("load_scene: a missing scene file is an error naming it", "[base]") {
    CHECK_THROWS_WITH(load_scene(kData / "no-such-scene.test"),
                      Catch::Matchers::Contains("no-such-scene.test: scene file not found"));
}

TEST_CASE("parse_scene: reads image, camera and output settings", "[base]") {
    const Scene scene = parse("size 320 200\nmaxdepth 3\noutput picture.png\n" + kCamera);
    CHECK(scene.width == 320);
    CHECK(scene.height == 200);
    CHECK(scene.max_depth == 3);
    CHECK(scene.output == "picture.png");
    CHECK(scene.camera.lookfrom == Vec3(0, 0, 5));
    CHECK(scene.camera.lookat == Vec3(0, 0, 0));
    CHECK(scene.camera.up == Vec3(0, 1, 0));
    CHECK(scene.camera.fovy_degrees == 45.0);
    CHECK(scene.camera.line == 4);
    CHECK_FALSE(scene.camera.ortho);
}

TEST_CASE("parse_scene: defaults are those of the CSE167 format", "[base]") {
    const Scene scene = parse(kCamera + "sphere 0 0 0 1\npoint 1 1 1 1 1 1\n");
    CHECK(scene.width == 640);
    CHECK(scene.height == 480);
    CHECK(scene.max_depth == 5);
    CHECK(scene.output.empty());
    const Material& m = scene.materials.at(scene.spheres.at(0).attributes.material);
    CHECK(m.ambient == Color(0.2));
    CHECK(m.diffuse == Color(0.0));
    CHECK(m.specular == Color(0.0));
    CHECK(m.emission == Color(0.0));
    CHECK(m.shininess == 0.0);
    const Attenuation& a = scene.point_lights.at(0).attenuation;
    CHECK(a.constant == 1.0);
    CHECK(a.linear == 0.0);
    CHECK(a.quadratic == 0.0);
}

TEST_CASE("parse_scene: comments, blank lines, tabs and Windows line ends are ignored", "[base]") {
    const Scene scene = parse("# a comment\r\n\r\n  \t\r\n" + kCamera +
                              "sphere\t1 2 3 0.5   # trailing comment\r\n");
    REQUIRE(scene.spheres.size() == 1);
    CHECK(scene.spheres[0].shape.center == Vec3(1, 2, 3));
    CHECK(scene.spheres[0].shape.radius == 0.5);
    CHECK(scene.spheres[0].attributes.line == 5);
}

TEST_CASE("parse_scene: tri resolves vertex indices in the order vertices were given", "[base]") {
    const Scene scene = parse(kCamera +
                              "maxverts 4\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
                              "vertex 0 1 0\ntri 0 1 2\ntri 0 2 3\n");
    REQUIRE(scene.triangles.size() == 2);
    CHECK(scene.triangles[1].shape.p0 == Vec3(0, 0, 0));
    CHECK(scene.triangles[1].shape.p1 == Vec3(1, 1, 0));
    CHECK(scene.triangles[1].shape.p2 == Vec3(0, 1, 0));
    CHECK(scene.triangles[1].vertex_normals == -1);
    CHECK(scene.triangles[1].mesh == -1);
}

TEST_CASE("parse_scene: trinormal keeps the per-vertex normals", "[base]") {
    const Scene scene = parse(kCamera +
                              "maxvertnorms 3\nvertexnormal 0 0 0 0 0 1\n"
                              "vertexnormal 1 0 0 0 1 1\nvertexnormal 0 1 0 1 0 1\n"
                              "trinormal 0 1 2\n");
    REQUIRE(scene.triangles.size() == 1);
    const SceneTriangle& t = scene.triangles[0];
    CHECK(t.shape.p1 == Vec3(1, 0, 0));
    REQUIRE(t.vertex_normals == 0);
    CHECK(scene.vertex_normals.at(0).n1 == Vec3(0, 1, 1));
    CHECK(scene.vertex_normals.at(0).n2 == Vec3(1, 0, 1));
}

TEST_CASE("parse_scene: the material in force is the one an object gets", "[base]") {
    const Scene scene = parse(kCamera +
                              "diffuse 1 0 0\nsphere 0 0 0 1\nsphere 1 0 0 1\n"
                              "specular 0.5 0.5 0.5\nshininess 20\nemission 0 0 0.1\n"
                              "ambient 0 0 0\nsphere 2 0 0 1\n");
    REQUIRE(scene.spheres.size() == 3);
    CHECK(scene.spheres[0].attributes.material == scene.spheres[1].attributes.material);
    CHECK(scene.materials.size() == 2);  // a material is stored once, not per object
    const Material& second = scene.materials.at(scene.spheres[2].attributes.material);
    CHECK(second.diffuse == Color(1, 0, 0));
    CHECK(second.specular == Color(0.5));
    CHECK(second.shininess == 20.0);
    CHECK(second.emission == Color(0, 0, 0.1));
    CHECK(second.ambient == Color(0.0));
}

TEST_CASE("parse_scene: transforms right-multiply and pushTransform saves the stack", "[base]") {
    const Scene scene =
        parse(kCamera +
              "sphere 0 0 0 1\n"
              "translate 1 0 0\n"
              "pushTransform\nrotate 0 1 0 90\nscale 2 2 2\nsphere 0 0 0 1\npopTransform\n"
              "sphere 0 0 0 1\n");
    REQUIRE(scene.spheres.size() == 3);
    CHECK(scene.spheres[0].attributes.transform == 0);  // the identity
    const std::vector<TransformOp> inner =
        transform_ops(scene, scene.spheres[1].attributes.transform);
    REQUIRE(inner.size() == 3);
    CHECK(inner[0].kind == TransformOp::Kind::translate);
    CHECK(inner[0].vector == Vec3(1, 0, 0));
    CHECK(inner[1].kind == TransformOp::Kind::rotate);
    CHECK(inner[1].vector == Vec3(0, 1, 0));
    CHECK(inner[1].angle_degrees == 90.0);
    CHECK(inner[2].kind == TransformOp::Kind::scale);
    const std::vector<TransformOp> outer =
        transform_ops(scene, scene.spheres[2].attributes.transform);
    REQUIRE(outer.size() == 1);  // popTransform restored "translate 1 0 0"
    CHECK(outer[0].vector == Vec3(1, 0, 0));
}

TEST_CASE("parse_scene: objects under one stack state share one transform", "[base]") {
    const Scene scene = parse(kCamera +
                              "translate 0 1 0\nsphere 0 0 0 1\nsphere 1 0 0 1\n"
                              "pushTransform\nsphere 2 0 0 1\npopTransform\n");
    const std::uint32_t shared = scene.spheres[0].attributes.transform;
    CHECK(shared != 0);
    CHECK(scene.spheres[1].attributes.transform == shared);
    CHECK(scene.spheres[2].attributes.transform == shared);
}

TEST_CASE("parse_scene: transforms that change nothing need no matrix", "[base]") {
    const Scene scene =
        parse(kCamera + "translate 0 0 0\nscale 1 1 1\nrotate 0 0 1 0\nsphere 0 0 0 1\n");
    CHECK(scene.spheres[0].attributes.transform == 0);
}

TEST_CASE("parse_scene: a deep transform stack costs memory in proportion to the file", "[base]") {
    // Each object's transform is a node in a tree, not a copy of every op above it: copies would
    // hold 20,000 x 20,001 / 2 = 2 x 10^8 ops for 20,000 nested pushTransform/translate pairs with
    // a sphere each, a file under 1 MB.
    std::ostringstream text;
    text << kCamera;
    for (int k = 0; k < 20000; ++k)
        text << "pushTransform\ntranslate 0 0 1\nsphere 0 0 0 1\n";
    const Scene scene = parse(text.str());
    REQUIRE(scene.spheres.size() == 20000);
    CHECK(scene.transforms.size() == 20001);  // the root and one node per translate
    CHECK(transform_ops(scene, scene.spheres.back().attributes.transform).size() == 20000);
}

TEST_CASE("parse_scene: old Mac line ends (a lone CR) separate lines too", "[base]") {
    const Scene scene = parse("camera 0 0 5 0 0 0 0 1 0 45\rsphere 1 2 3 0.5\rsphere 0 0 0 1\r\n");
    REQUIRE(scene.spheres.size() == 2);
    CHECK(scene.spheres[1].attributes.line == 3);
}

TEST_CASE("parse_scene: lights keep the attenuation in force when they were given", "[base]") {
    const Scene scene = parse(kCamera +
                              "point 1 2 3 0.5 0.5 0.5\nattenuation 1 0.1 0.01\n"
                              "point 0 5 0 1 1 1\ndirectional 0 -1 0 0.2 0.2 0.2\n");
    REQUIRE(scene.point_lights.size() == 2);
    CHECK(scene.point_lights[0].position == Vec3(1, 2, 3));
    CHECK(scene.point_lights[0].attenuation.linear == 0.0);
    CHECK(scene.point_lights[1].attenuation.linear == 0.1);
    CHECK(scene.point_lights[1].attenuation.quadratic == 0.01);
    REQUIRE(scene.directional_lights.size() == 1);
    CHECK(scene.directional_lights[0].direction == Vec3(0, -1, 0));
    CHECK(scene.directional_lights[0].color == Color(0.2));
}

TEST_CASE("parse_scene: plane and ortho extensions", "[base]") {
    const Scene scene = parse(kCamera + "ortho -2 2 -1.5 1.5\nplane 0 -1 0 0 1 0\n");
    REQUIRE(scene.camera.ortho);
    CHECK(scene.camera.ortho->left == -2.0);
    CHECK(scene.camera.ortho->top == 1.5);
    REQUIRE(scene.planes.size() == 1);
    CHECK(scene.planes[0].shape.point == Vec3(0, -1, 0));
    CHECK(scene.planes[0].shape.normal == Vec3(0, 1, 0));
}

TEST_CASE("parse_scene: rayoffset picks the rule shadow and mirror rays start by", "[base]") {
    CHECK(parse(kCamera).ray_offset == RayOffset{OffsetRule::error_bound, 0.0});
    CHECK(parse(kCamera + "rayoffset along-ray 1e-4\n").ray_offset ==
          RayOffset{OffsetRule::along_ray, 1e-4});
    CHECK(parse(kCamera + "rayoffset along-normal 0.5\n").ray_offset ==
          RayOffset{OffsetRule::along_normal, 0.5});
    CHECK(parse(kCamera + "rayoffset error-bound\n").ray_offset ==
          RayOffset{OffsetRule::error_bound, 0.0});
}

TEST_CASE("parse_scene: mesh loads a file relative to the scene and records it", "[base]") {
    const Scene scene = parse(kCamera + "diffuse 0 1 0\nmesh meshes/square.off\nsphere 0 0 0 1\n");
    REQUIRE(scene.meshes.size() == 1);
    CHECK(scene.meshes[0].triangle_count == 2);
    CHECK(scene.meshes[0].first_triangle == 0);
    CHECK(scene.meshes[0].line == 3);
    REQUIRE(scene.triangles.size() == 2);
    CHECK(scene.triangles[0].mesh == 0);
    CHECK(scene.materials.at(scene.triangles[0].attributes.material).diffuse == Color(0, 1, 0));
    CHECK(scene.spheres.size() == 1);
}

TEST_CASE(
    "parse_scene: a mesh's vertex normals make its triangles smooth where every corner "
    "has one",
    "[base]") {
    const Scene scene = parse(kCamera + "mesh meshes/normals.obj\n");
    REQUIRE(scene.triangles.size() == 3);
    REQUIRE(scene.triangles[0].vertex_normals >= 0);
    const VertexNormals& n =
        scene.vertex_normals[static_cast<std::size_t>(scene.triangles[0].vertex_normals)];
    CHECK(n.n1 == Vec3(0, 0, 2));
    CHECK(n.n2 == Vec3(1, 0, 1));
    CHECK(scene.triangles[1].vertex_normals >= 0);
    CHECK(scene.triangles[2].vertex_normals == -1);
}

TEST_CASE("parse_scene: mesh FILE smooth gives every triangle its vertices' area-weighted normals",
          "[base]") {
    const Scene flat = parse(kCamera + "mesh meshes/square.obj\n");
    CHECK(flat.triangles[0].vertex_normals == -1);
    const Scene smooth = parse(kCamera + "mesh meshes/square.obj smooth\n");
    REQUIRE(smooth.triangles.size() == 2);
    for (const SceneTriangle& triangle : smooth.triangles) {
        REQUIRE(triangle.vertex_normals >= 0);
        // A flat square: every vertex's faces face +z.
        const VertexNormals& n =
            smooth.vertex_normals[static_cast<std::size_t>(triangle.vertex_normals)];
        CHECK(glm::normalize(n.n0) == Vec3(0, 0, 1));
        CHECK(glm::normalize(n.n2) == Vec3(0, 0, 1));
    }
}

TEST_CASE("parse_scene: a defined mesh keeps each face's vertex normals and uvs, as mesh does",
          "[base]") {
    const Scene scene =
        parse(kCamera +
              "define ball meshes/normals.obj\ninstance ball\n"
              "define quad meshes/uvs.obj\ndefine square meshes/square.obj smooth\n");
    CHECK(scene.notes.empty());
    REQUIRE(scene.mesh_definitions.size() == 3);
    const MeshDefinition& ball = scene.mesh_definitions[0];
    REQUIRE(ball.vertex_normals.size() == 3);
    REQUIRE(ball.vertex_normals[0] >= 0);
    CHECK(scene.vertex_normals[static_cast<std::size_t>(ball.vertex_normals[0])].n1 ==
          Vec3(0, 0, 2));
    CHECK(ball.vertex_normals[2] == -1);  // a face with a corner that names no normal
    const MeshDefinition& quad = scene.mesh_definitions[1];
    REQUIRE(quad.vertex_uvs.size() == 2);
    REQUIRE(quad.vertex_uvs[0] >= 0);
    CHECK(scene.vertex_uvs[static_cast<std::size_t>(quad.vertex_uvs[0])].uv2 == Vec2(1, 1));
    // smooth: normals made at the vertices, as for mesh FILE smooth.
    CHECK(scene.mesh_definitions[2].vertex_normals[0] >= 0);
    CHECK(scene_features(scene).smooth_triangles == 2);  // the ball's, placed once
}

TEST_CASE("parse_scene: texture, normalmap and bumpmap set the maps of the objects after them",
          "[base]") {
    // Any regular file will do: the loader checks that it is there, the renderer reads it.
    const Scene scene = parse(kCamera +
                              "texture meshes/square.obj\nsphere 0 0 0 1\n"
                              "texture meshes/square.obj clamp\nbumpmap meshes/square.off 0.5\n"
                              "sphere 2 0 0 1\n"
                              "texture off\nnormalmap meshes/square.off mirror\nsphere 4 0 0 1\n"
                              "normalmap off\nsphere 6 0 0 1\n");
    REQUIRE(scene.textures.size() == 4);
    CHECK(scene.textures[0].wrap == WrapMode::repeat);
    CHECK(scene.textures[1].wrap == WrapMode::clamp);  // one file, two wrap modes: two textures
    CHECK(scene.textures[1].line == 4);
    const auto material = [&](std::size_t k) {
        return scene.materials[scene.spheres[k].attributes.material];
    };
    CHECK(material(0).diffuse_map == 0);
    CHECK(material(1).diffuse_map == 1);
    CHECK(material(1).bump_map == 2);
    CHECK(material(1).bump_scale == 0.5);
    CHECK(material(2).diffuse_map == -1);
    CHECK(material(2).normal_map == 3);
    CHECK(material(2).bump_map == -1);  // a normal map replaces the bump map
    CHECK_FALSE(material(3).has_maps());
}

TEST_CASE(
    "parse_scene: a mesh face with an MTL material takes its Kd and maps, the rest as in "
    "force",
    "[base]") {
    const Scene scene =
        parse(kCamera + "diffuse 0 1 0\nspecular 0.3 0.3 0.3\nmesh meshes/materials.obj\n");
    REQUIRE(scene.triangles.size() == 6);
    const auto material = [&](std::size_t k) {
        return scene.materials[scene.triangles[k].attributes.material];
    };
    // Before any usemtl: the material in force.
    CHECK(material(0).diffuse == Color(0, 1, 0));
    CHECK_FALSE(material(0).has_maps());
    // "painted": its Kd and its clamped diffuse map; the scene's specular kept.
    CHECK(material(1).diffuse.r == Approx(0.8));
    CHECK(material(1).specular == Color(0.3, 0.3, 0.3));
    REQUIRE(material(1).diffuse_map >= 0);
    CHECK(scene.textures[static_cast<std::size_t>(material(1).diffuse_map)].wrap ==
          WrapMode::clamp);
    CHECK(scene.triangles[2].attributes.material == scene.triangles[1].attributes.material);
    // "bricks": a normal map and a bump map, of which the normal map shades, as with normalmap.
    CHECK(material(3).normal_map >= 0);
    CHECK(material(3).bump_map == -1);
    CHECK(scene.textures[static_cast<std::size_t>(material(3).normal_map)].line ==
          4);  // the mesh's
    // "bumped": a bump map alone, at the MTL's -bm.
    CHECK(material(5).bump_map >= 0);
    CHECK(material(5).bump_scale == Approx(0.05));
}

TEST_CASE("parse_scene: a defined mesh's MTL materials are noted as unused by its instances",
          "[base]") {
    const Scene scene = parse(kCamera + "define wall meshes/materials.obj\ninstance wall\n");
    REQUIRE(scene.notes.size() == 1);
    CHECK_THAT(scene.notes[0].text, Catch::Matchers::Contains("MTL materials are not used"));
}

TEST_CASE("parse_scene: triuv keeps the vertices' texture coordinates, as a mesh's vt do",
          "[base]") {
    const Scene scene = parse(kCamera +
                              "vertexuv 0 0 0 0 0\nvertexuv 1 0 0 2 0\nvertexuv 0 1 0 0 3\n"
                              "triuv 0 1 2\nmesh meshes/uvs.obj\n");
    REQUIRE(scene.triangles.size() == 3);
    REQUIRE(scene.triangles[0].vertex_uvs >= 0);
    const VertexUvs& uvs =
        scene.vertex_uvs[static_cast<std::size_t>(scene.triangles[0].vertex_uvs)];
    CHECK(uvs.uv1 == Vec2(2, 0));
    CHECK(uvs.uv2 == Vec2(0, 3));
    CHECK(scene.triangles[1].vertex_uvs >= 0);
    CHECK(scene.triangles[1].vertex_normals >= 0);
}

TEST_CASE("parse_scene: a mesh between vertex commands does not shift tri indices", "[base]") {
    const Scene scene = parse(kCamera +
                              "vertex 5 0 0\nmesh meshes/square.obj\nvertex 6 0 0\n"
                              "vertex 7 0 0\ntri 0 1 2\n");
    REQUIRE(scene.triangles.size() == 3);
    CHECK(scene.triangles[2].shape.p0 == Vec3(5, 0, 0));
    CHECK(scene.triangles[2].shape.p2 == Vec3(7, 0, 0));
}

TEST_CASE("parse_scene: a scene of 100,000 triangles loads whole", "[base]") {
    // The size of bunny00.off. `raystep info` on the same text takes well under a second
    // (docs/scene-format.md gives the measurement and the command that makes it).
    std::ostringstream text;
    text << kCamera << "maxverts 50002\n";
    for (int k = 0; k < 50002; ++k)
        text << "vertex " << k << " " << (k % 2) << " 0.5\n";
    for (int k = 0; k < 100000; ++k)
        text << "tri " << k / 2 << " " << k / 2 + 1 << " " << k / 2 + 2 << "\n";
    const Scene scene = parse(text.str());
    REQUIRE(scene.triangles.size() == 100000);
    CHECK(scene.triangles.back().shape.p2 == Vec3(50001, 1, 0.5));
    CHECK(scene.triangles.back().attributes.line == 2 + 50002 + 100000);
}

TEST_CASE("parse_scene: quadLight is a corner, two edges and a radiance in world coordinates",
          "[base]") {
    const Scene scene = parse(kCamera +
                              "translate 5 0 0\nscale 2 2 2\n"
                              "quadLight -1 2 -1  2 0 0  0 0 2  10 8 6\n");
    REQUIRE(scene.quad_lights.size() == 1);
    const QuadLight& light = scene.quad_lights[0];
    CHECK(light.corner == Vec3(-1, 2, -1));  // the transform in force moves no light
    CHECK(light.edge1 == Vec3(2, 0, 0));
    CHECK(light.edge2 == Vec3(0, 0, 2));
    CHECK(light.radiance == Color(10, 8, 6));
    CHECK(light.line == 4);
}

TEST_CASE("parse_scene: spot keeps its cone and the attenuation in force", "[base]") {
    const Scene scene =
        parse(kCamera + "attenuation 1 0 0.5\nspot 0 3 0  0 -1 0  30 4  1 0.5 0.25\n");
    REQUIRE(scene.spot_lights.size() == 1);
    const SpotLight& light = scene.spot_lights[0];
    CHECK(light.position == Vec3(0, 3, 0));
    CHECK(light.direction == Vec3(0, -1, 0));
    CHECK(light.cutoff_degrees == 30.0);
    CHECK(light.exponent == 4.0);
    CHECK(light.color == Color(1, 0.5, 0.25));
    CHECK(light.attenuation.quadratic == 0.5);
    CHECK(light.line == 3);
    CHECK(parse(kCamera + "spot 0 3 0 0 -1 0 90 0 1 1 1\n").spot_lights.at(0).cutoff_degrees ==
          90.0);
}

TEST_CASE("parse_scene: transmission and ior are material state like specular", "[base]") {
    const Scene scene = parse(kCamera +
                              "sphere 0 0 0 1\ntransmission 0.9 0.8 0.7\nior 1.5\n"
                              "sphere 1 0 0 1\nior 1.33\nsphere 2 0 0 1\n");
    const auto material = [&](std::size_t k) {
        return scene.materials.at(scene.spheres.at(k).attributes.material);
    };
    CHECK(material(0).transmission == Color(0.0));
    CHECK(material(0).index == 1.0);
    CHECK(material(1).transmission == Color(0.9, 0.8, 0.7));
    CHECK(material(1).index == 1.5);
    CHECK(material(2).transmission == Color(0.9, 0.8, 0.7));
    CHECK(material(2).index == 1.33);
}

TEST_CASE("parse_scene: sampling settings and their defaults", "[base]") {
    const Scene defaults = parse(kCamera);
    CHECK(defaults.samples_per_pixel == 1);
    CHECK(defaults.pixel_sampling == SamplePattern::jittered);
    CHECK(defaults.light_samples == 1);
    CHECK_FALSE(defaults.light_stratify);
    CHECK(defaults.seed == 0);
    CHECK(defaults.background == Color(0.0));
    CHECK_FALSE(defaults.schlick_fresnel);
    CHECK(defaults.notes.empty());

    const Scene scene = parse(kCamera +
                              "spp 16\npixelsampling regular\nlightsamples 9\nlightstratify on\n"
                              "seed 18446744073709551615\nbackground 0.1 0.2 0.3\n"
                              "fresnel schlick\n");
    CHECK(scene.samples_per_pixel == 16);
    CHECK(scene.pixel_sampling == SamplePattern::regular);
    CHECK(scene.light_samples == 9);
    CHECK(scene.light_stratify);
    CHECK(scene.seed == 18446744073709551615ull);
    CHECK(scene.background == Color(0.1, 0.2, 0.3));
    CHECK(scene.schlick_fresnel);
    CHECK(scene.notes.empty());

    CHECK(parse(kCamera + "pixelsampling random\nspp 7\n").pixel_sampling == SamplePattern::random);
    CHECK(parse(kCamera + "lightstratify off\nlightsamples 7\n").light_samples == 7);
    CHECK(parse(kCamera + "spp 65536\n").samples_per_pixel == 65536);
}

TEST_CASE("parse_scene: a non-square spp under the default pattern is sampled at random, noted",
          "[base]") {
    // The CSE168 course takes any spp; raystep's default, jittered, needs n x n.
    const Scene scene = parse(kCamera + "spp 8\n");
    CHECK(scene.samples_per_pixel == 8);
    CHECK(scene.pixel_sampling == SamplePattern::random);
    REQUIRE(scene.notes.size() == 1);
    CHECK(scene.notes[0].line == 2);
    CHECK(scene.notes[0].command == "spp");
    CHECK_THAT(scene.notes[0].text, Catch::Matchers::Contains("not a square"));
    CHECK(warning_text(scene, scene.notes[0]).rfind("inline.test:2: warning: spp 8", 0) == 0);
}

TEST_CASE("parse_scene: integrator pathtracer reads its settings and each material's BRDF",
          "[base]") {
    const Scene scene = parse(kCamera +
                              "integrator pathtracer\nnexteventestimation mis\n"
                              "russianroulette on\nimportancesampling cosine\ngamma 2.2\n"
                              "brdf ggx\nroughness 0.25\nsphere 0 0 0 1\nbrdf phong\n"
                              "roughness 0\nsphere 1 0 0 1\n");
    CHECK(scene.next_event == NextEvent::mis);
    CHECK(scene.russian_roulette);
    CHECK(scene.importance_sampling == DirectionSampling::cosine);
    REQUIRE(scene.spheres.size() == 2);
    const Material& first = scene.materials[scene.spheres[0].attributes.material];
    const Material& second = scene.materials[scene.spheres[1].attributes.material];
    CHECK(first.brdf == BrdfModel::ggx);
    CHECK(first.roughness == 0.25);
    CHECK(second.brdf == BrdfModel::phong);
    CHECK(second.roughness == 0.0);
    // Only what the path tracer does not use is noted: gamma, and the ambient the CSE168
    // dialect leaves at 0.
    std::vector<std::string> noted;
    for (const SceneNote& note : scene.notes)
        noted.push_back(note.command + "@" + std::to_string(note.line));
    CHECK(noted == std::vector<std::string>{"integrator@2", "gamma@6", "sphere@9"});
}

TEST_CASE("parse_scene: under integrator pathtracer what its paths do not use is noted", "[base]") {
    const Scene scene =
        parse(kCamera +
              "integrator pathtracer\npoint 0 5 0 1 1 1\nbackground 1 1 1\nlightsamples 4\n"
              "transmission 1 1 1\nior 1.5\nambient 0 0 0\nsphere 0 0 0 1\n");
    std::vector<std::string> noted;
    for (const SceneNote& note : scene.notes)
        noted.push_back(note.command + "@" + std::to_string(note.line));
    CHECK(noted == std::vector<std::string>{"integrator@2", "point@3", "background@4",
                                            "lightsamples@5", "transmission@6", "ior@7"});
    CHECK_THAT(scene.notes[1].text,
               Catch::Matchers::Contains("lit by quad lights and emitting surfaces only"));
}

TEST_CASE("parse_scene: a path tracer's material of albedo 1 with no depth limit is noted",
          "[base]") {
    // Russian roulette cannot end a path whose weight stays 1: it stops after kLongestPath.
    const std::string paths =
        kCamera + "integrator pathtracer\nmaxdepth -1\nrussianroulette on\nambient 0 0 0\n";
    const Scene white = parse(paths + "diffuse 0.6 1 0.6\nsphere 0 0 0 1\n");
    REQUIRE(white.notes.size() == 2);
    CHECK(white.notes[1].command == "maxdepth");
    CHECK(white.notes[1].line == 3);
    CHECK_THAT(white.notes[1].text, Catch::Matchers::Contains("stop after 1000 bounces"));
    CHECK(parse(paths + "diffuse 0.6 0.9 0.6\nsphere 0 0 0 1\n").notes.size() == 1);
}

TEST_CASE("parse_scene: the path tracer's settings under another integrator are each noted once",
          "[base]") {
    const Scene scene = parse(kCamera +
                              "integrator direct\nnexteventestimation mis\n"
                              "russianroulette on\nimportancesampling cosine\ngamma 2.2\n"
                              "brdf ggx\nroughness 0.25\nsphere 0 0 0 1\nbrdf ggx\n"
                              "roughness 0\nsphere 1 0 0 1\n");
    CHECK(scene.spheres.size() == 2);
    std::vector<std::string> noted;
    for (const SceneNote& note : scene.notes)
        noted.push_back(note.command + "@" + std::to_string(note.line));
    CHECK(noted == std::vector<std::string>{"integrator@2", "nexteventestimation@3",
                                            "russianroulette@4", "importancesampling@5", "gamma@6",
                                            "brdf@7", "roughness@8", "sphere@9"});
}

TEST_CASE("parse_scene: notes come in file order, the end-of-file spp note among them", "[base]") {
    const Scene scene = parse(kCamera + "gamma 2.2\nspp 8\nrussianroulette off\n");
    REQUIRE(scene.notes.size() == 3);
    CHECK(scene.notes[0].command == "gamma");
    CHECK(scene.notes[1].command == "spp");
    CHECK(scene.notes[1].line == 3);
    CHECK(scene.notes[2].command == "russianroulette");
}

TEST_CASE("parse_scene: integrator direct, analyticdirect and pathtracer read the CSE168 dialect",
          "[base]") {
    const Scene plain = parse(kCamera + "sphere 0 0 0 1\n");
    CHECK(plain.dialect == SceneDialect::cse167);
    const Scene raytracer = parse(kCamera + "integrator raytracer\n");
    CHECK(raytracer.dialect == SceneDialect::cse167);
    CHECK(raytracer.notes.empty());
    for (const std::string integrator : {"direct", "analyticdirect", "pathtracer"}) {
        CAPTURE(integrator);
        const Scene scene = parse(kCamera + "integrator " + integrator + "\n");
        CHECK(scene.dialect == SceneDialect::cse168);
        REQUIRE(scene.notes.size() == 1);
        CHECK(scene.notes[0].line == 2);
        CHECK_THAT(scene.notes[0].text, Catch::Matchers::Contains("read in the CSE168 dialect"));
    }
    const Scene analytic = parse(kCamera + "integrator analyticdirect\n");
    CHECK_THAT(analytic.notes[0].text, Catch::Matchers::Contains("integrated exactly"));
}

TEST_CASE(
    "parse_scene: the dialect is the whole file's, so a material above the integrator "
    "has no ambient",
    "[base]") {
    // CSE167's default ambient is 0.2; the CSE168 path tracer has none unless it is written.
    const std::string objects = "sphere 0 0 0 1\nambient 0.1 0.1 0.1\nsphere 2 0 0 1\n";
    const Scene cse167 = parse(kCamera + objects);
    CHECK(cse167.materials.front().ambient == Color(0.2));
    const Scene cse168 = parse(kCamera + objects + "integrator direct\n");
    REQUIRE(cse168.materials.size() == 2);
    CHECK(cse168.materials[0].ambient == Color(0.0));
    CHECK(cse168.materials[1].ambient == Color(0.1));
    // The default is noted once, on the first object that takes it.
    std::vector<std::uint32_t> ambient_notes;
    for (const SceneNote& note : cse168.notes) {
        if (note.text.find("no 'ambient'") != std::string::npos) ambient_notes.push_back(note.line);
    }
    CHECK(ambient_notes == std::vector<std::uint32_t>{2});
    const Scene written = parse(kCamera + "integrator direct\nambient 0 0 0\n" + objects);
    for (const SceneNote& note : written.notes)
        CHECK(note.text.find("no 'ambient'") == std::string::npos);
}

TEST_CASE("parse_scene: in the CSE168 dialect more vertices than maxverts are a warning, and kept",
          "[base]") {
    // The course's own hw4 mis.test declares 28 vertices and gives 32.
    const std::string vertices = "maxverts 2\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n";
    CHECK_THROWS_WITH(parse(kCamera + vertices),
                      "inline.test:5: more vertices than 'maxverts 2' declared");
    const Scene scene = parse(kCamera + "integrator direct\n" + vertices + "tri 0 1 2\n");
    CHECK(scene.triangles.size() == 1);
    REQUIRE(scene.notes.size() >= 2);
    const SceneNote& vertex = scene.notes[1];
    CHECK(vertex.line == 6);
    CHECK(vertex.command == "vertex");
    CHECK_THAT(vertex.text, Catch::Matchers::Contains("reads the count as a declaration"));
    // The same for a count below the vertices already given, and for vertexnormals.
    const std::string late = "vertex 0 0 0\nvertex 1 0 0\nmaxverts 1\n";
    CHECK_THROWS_WITH(parse(kCamera + late),
                      "inline.test:4: maxverts 1 is less than the 2 vertices already given");
    CHECK(parse(kCamera + "integrator direct\n" + late).notes.back().command == "maxverts");
    const std::string normals =
        "maxvertnorms 1\nvertexnormal 0 0 0 0 0 1\nvertexnormal 1 0 0 0 0 1\n";
    CHECK_THROWS_WITH(parse(kCamera + normals),
                      "inline.test:4: more vertexnormals than 'maxvertnorms 1' declared");
    CHECK(parse(kCamera + "integrator direct\n" + normals).notes.back().command == "vertexnormal");
}

TEST_CASE("parse_scene: a malformed integrator line is reported as itself, before the lines above",
          "[base]") {
    // The dialect it fails to set would make the maxdepth -1 above it an error of its own.
    CHECK_THROWS_WITH(parse(kCamera + "maxdepth -1\nintegrator pathtracing\n"),
                      "inline.test:3: 'integrator' takes raytracer, direct, analyticdirect or "
                      "pathtracer, not 'pathtracing'");
    CHECK_THROWS_WITH(parse(kCamera + "maxdepth -1\nintegrator direct 2\n"),
                      Catch::Matchers::StartsWith("inline.test:3: 'integrator' takes 1 argument"));
    // A second integrator is still the error of the second line.
    CHECK_THROWS_WITH(parse(kCamera + "integrator direct\nintegrator raytracer\n"),
                      "inline.test:3: 'integrator' was already given on line 2");
}

TEST_CASE("parse_scene: under analyticdirect the light samples are noted as having no effect",
          "[base]") {
    const Scene scene =
        parse(kCamera + "lightsamples 16\nlightstratify on\nintegrator analyticdirect\n");
    std::vector<std::string> noted;
    for (const SceneNote& note : scene.notes)
        noted.push_back(note.command + "@" + std::to_string(note.line));
    CHECK(noted == std::vector<std::string>{"lightsamples@2", "lightstratify@3", "integrator@4"});
    CHECK_THAT(scene.notes[0].text,
               Catch::Matchers::Contains("integrates each quad light exactly"));
    CHECK(parse(kCamera + "lightsamples 16\nintegrator direct\n").notes.size() == 1);
}

TEST_CASE("parse_scene: maxdepth -1 is no limit in the CSE168 dialect, and an error in CSE167's",
          "[base]") {
    // The direct integrator traces no paths: the limit is noted as having no use.
    const Scene scene = parse(kCamera + "integrator direct\nmaxdepth -1\n");
    CHECK(scene.max_depth == kUnboundedDepth);
    REQUIRE(scene.notes.size() == 2);
    CHECK(scene.notes[1].command == "maxdepth");
    CHECK_THAT(scene.notes[1].text, Catch::Matchers::Contains("sets no limit"));
    // The path tracer ends its paths by Russian roulette, which must be on.
    const Scene paths = parse(kCamera + "integrator pathtracer\nmaxdepth -1\nrussianroulette on\n");
    CHECK(paths.max_depth == kUnboundedDepth);
    CHECK(paths.notes.size() == 1);
    CHECK_THROWS_WITH(parse(kCamera + "integrator pathtracer\nmaxdepth -1\n"),
                      Catch::Matchers::StartsWith("inline.test:3: maxdepth -1 (no limit) under"));
    CHECK_THROWS_WITH(parse(kCamera + "maxdepth -1\n"),
                      Catch::Matchers::StartsWith("inline.test:2: maxdepth -1 (no limit) is the "
                                                  "CSE168 dialect's"));
}

TEST_CASE("scene_features: in the CSE168 dialect specular is a lobe, not a mirror", "[base]") {
    const std::string shiny = "specular 0.5 0.5 0.5\nsphere 0 0 0 1\n";
    CHECK(scene_features(parse(kCamera + shiny)).reflective_objects == 1);
    const Scene cse168 = parse(kCamera + "integrator direct\n" + shiny);
    CHECK(scene_features(cse168).reflective_objects == 0);
    bool specular_noted = false;
    for (const SceneNote& note : cse168.notes)
        specular_noted = specular_noted || (note.command == "specular" && note.line == 3);
    CHECK(specular_noted);
}

TEST_CASE("load_scene: a CSE168 Cornell box lit by a quadLight loads as the course writes it",
          "[base]") {
    const Scene scene = load_scene(kData / "good" / "cornell_quadlight.test");
    CHECK(scene.quad_lights.size() == 1);
    CHECK(scene.samples_per_pixel == 4);
    CHECK(scene.pixel_sampling == SamplePattern::jittered);
    CHECK(scene.light_samples == 16);
    CHECK(scene.light_stratify);
    CHECK(scene.triangles.size() == 10);
    CHECK(scene.dialect == SceneDialect::cse168);
    // It writes its ambient, so the dialect's notes are the integrator's and the drawn light's.
    std::vector<std::string> noted;
    for (const SceneNote& note : scene.notes)
        noted.push_back(note.command + "@" + std::to_string(note.line));
    CHECK(noted == std::vector<std::string>{"integrator@9", "quadLight@29"});
}
