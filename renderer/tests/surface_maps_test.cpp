#include "renderer/surface_maps.h"

#include <cstdint>
#include <fstream>
#include <optional>
#include <string>

#include <glm/geometric.hpp>

#include "base/image/image_io.h"
#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "base/testing/filled_image.h"
#include "base/testing/scratch_folder.h"
#include "renderer/render_pixel.h"
#include "renderer/surface_point.h"
#include "stages/11_surface_detail/surface_detail.h"

using namespace raystep;
using raystep::testing::filled_image;
using raystep::testing::ScratchFolder;

namespace {

// A 2 x 2 image of four colours, written as EXR so that its floats come back exactly.
Image four_texels() {
    Image image(2, 2);
    image.set(0, 0, {1, 0, 0});
    image.set(1, 0, {0, 1, 0});
    image.set(0, 1, {0, 0, 1});
    image.set(1, 1, {1, 1, 1});
    return image;
}

// A unit square in z = 0 facing the eye at +z, as two triangles with texture coordinates 0 to 1,
// under the maps `maps` (scene commands).
std::string textured_square(const std::string& maps) {
    return "camera 0 0 5 0 0 0 0 1 0 45\ndiffuse 0.5 1 1\n" + maps +
           "vertexuv 0 0 0 0 0\nvertexuv 1 0 0 1 0\nvertexuv 1 1 0 1 1\nvertexuv 0 1 0 0 1\n"
           "triuv 0 1 2\ntriuv 0 2 3\n";
}

struct MappedHit {
    Material material;
    SurfacePoint point;
    Vec2 uv;
};

// The material and point the maps make where the ray from (x, y, 5) straight down -z meets the
// scene, and the hit's texture coordinates by stage 11's interpolate_uv.
MappedHit mapped_at(const Scene& scene, double x, double y) {
    const RenderScene render_scene = prepare_render_scene(scene);
    const Ray ray{{x, y, 5}, {0, 0, -1}};
    const std::optional<PrimitiveHit> hit = scene_closest_hit(render_scene, ray, nullptr);
    REQUIRE(hit);
    SurfacePoint point = surface_point(render_scene, ray, *hit);
    const Material material =
        mapped_material(render_scene, ray, *hit, material_of(render_scene, *hit), point);
    // A triangle without texture coordinates has its barycentrics for them.
    const std::int32_t k = scene.triangles[hit->index].vertex_uvs;
    const VertexUvs uvs =
        k >= 0 ? scene.vertex_uvs[static_cast<std::size_t>(k)] : VertexUvs{{0, 0}, {1, 0}, {0, 1}};
    return {material, point,
            interpolate_uv(uvs.uv0, uvs.uv1, uvs.uv2, hit->hit.beta, hit->hit.gamma)};
}

}  // namespace

TEST_CASE("mapped_material: the diffuse colour is Kd times the texture's at the hit's uv",
          "[renderer]") {
    const ScratchFolder folder("surface-maps");
    const Image image = four_texels();
    write_image(image, folder.path() / "four.exr");
    const Scene scene = parse_scene(textured_square("texture four.exr\n"), "t.test", folder.path());
    for (const Vec2& at : {Vec2(0.25, 0.75), Vec2(0.6, 0.3), Vec2(0.9, 0.45)}) {
        const MappedHit mapped = mapped_at(scene, at.x, at.y);
        CAPTURE(at.x, at.y);
        const Color expected =
            Color(0.5, 1, 1) * texture_bilinear(image, mapped.uv, WrapMode::repeat);
        CHECK(glm::length(mapped.material.diffuse - expected) < 1e-12);
    }
    // (0.25, 0.75) is the top-left texel's centre: red, times Kd's 0.5.
    CHECK(glm::length(mapped_at(scene, 0.25, 0.75).material.diffuse - Color(0.5, 0, 0)) < 1e-6);
}

TEST_CASE("mapped_material: a flat normal map and a flat bump map leave the normal", "[renderer]") {
    const ScratchFolder folder("surface-maps");
    write_image(filled_image(4, 4, {0.5, 0.5, 1.0}), folder.path() / "flat-normals.exr");
    write_image(filled_image(4, 4, Color(0.3)), folder.path() / "flat-heights.exr");
    for (const char* maps : {"normalmap flat-normals.exr\n", "bumpmap flat-heights.exr 0.1\n"}) {
        CAPTURE(maps);
        const Scene scene = parse_scene(textured_square(maps), "t.test", folder.path());
        const MappedHit mapped = mapped_at(scene, 0.3, 0.6);
        CHECK(glm::length(mapped.point.shading_normal - Vec3(0, 0, 1)) < 1e-12);
    }
}

TEST_CASE("mapped_material: a flat bump map keeps a smooth triangle's interpolated normal",
          "[renderer]") {
    // Blinn's normal is built from dp/du and dp/dv across the normal that shades: from the flat
    // triangle's own, it would be the flat normal again.
    const ScratchFolder folder("surface-maps");
    write_image(filled_image(4, 4, Color(0.3)), folder.path() / "flat-heights.exr");
    const std::string smooth =
        "camera 0 0 5 0 0 0 0 1 0 45\nvertexnormal 0 0 0 0 0 1\nvertexnormal 1 0 0 1 0 1\n"
        "vertexnormal 0 1 0 0 1 1\n";
    const Scene plain = parse_scene(smooth + "trinormal 0 1 2\n", "t.test", folder.path());
    const Scene bumped = parse_scene(smooth + "bumpmap flat-heights.exr 0.1\ntrinormal 0 1 2\n",
                                     "t.test", folder.path());
    const RenderScene plain_scene = prepare_render_scene(plain);
    const Ray ray{{0.3, 0.2, 5}, {0, 0, -1}};
    const std::optional<PrimitiveHit> hit = scene_closest_hit(plain_scene, ray, nullptr);
    REQUIRE(hit);
    const Vec3 expected = surface_point(plain_scene, ray, *hit).shading_normal;
    CHECK(glm::length(mapped_at(bumped, 0.3, 0.2).point.shading_normal - expected) < 1e-12);
}

TEST_CASE("mapped_material: a bump map's slope tips the normal against it, on the eye's side",
          "[renderer]") {
    // Heights rising with u: each column's texel (i + 0.5) / 8, so h = u inside the image and the
    // slope along u is the scale, 0.25; along v, none.
    const ScratchFolder folder("surface-maps");
    Image ramp(8, 8);
    for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i)
            ramp.set(i, j, Color((i + 0.5) / 8));
    }
    write_image(ramp, folder.path() / "ramp.exr");
    const Scene scene =
        parse_scene(textured_square("bumpmap ramp.exr 0.25 clamp\n"), "t.test", folder.path());
    const MappedHit mapped = mapped_at(scene, 0.5, 0.5);
    CHECK(glm::length(mapped.point.shading_normal - glm::normalize(Vec3(-0.25, 0, 1))) < 1e-6);
    CHECK(mapped.point.normal == Vec3(0, 0, 1));  // the geometry's normal is not mapped
}

TEST_CASE("uv and tangent views: the hit's (u, v) less its floor, and the tangent as a colour",
          "[renderer]") {
    // One pixel, its ray straight down -z onto (0.8, 0.3) of a square whose texture coordinates
    // run to 2 along x: u = 1.6 shows as 0.6.
    const Scene scene = parse_scene(
        "size 1 1\ncamera 0.8 0.3 5 0.8 0.3 0 0 1 0 10\nvertexuv 0 0 0 0 0\nvertexuv 1 0 0 2 0\n"
        "vertexuv 1 1 0 2 1\nvertexuv 0 1 0 0 1\ntriuv 0 1 2\ntriuv 0 2 3\n",
        "views.test", ".");
    const RenderScene render_scene = prepare_render_scene(scene);
    CHECK(glm::length(render_pixel(render_scene, View::uv, 0, 0) - Color(0.6, 0.3, 0)) < 1e-9);
    // u grows along +x: the tangent (1, 0, 0) shows as (1, 0.5, 0.5).
    CHECK(glm::length(render_pixel(render_scene, View::tangent, 0, 0) - Color(1, 0.5, 0.5)) <
          1e-12);
}

TEST_CASE("prepare_render_scene: an image it cannot read names the scene line", "[renderer]") {
    const ScratchFolder folder("surface-maps");
    { std::ofstream(folder.path() / "broken.png") << "not an image"; }
    const Scene scene =
        parse_scene(textured_square("texture broken.png\n"), "t.test", folder.path());
    CHECK_THROWS_WITH(prepare_render_scene(scene), Catch::Matchers::Contains("t.test:3: "));
}
