// The commands of surface detail (docs/stage11.md, docs/scene-format.md "Textures"): the images a
// material looks up, and triangles with texture coordinates.

#include <filesystem>
#include <string>
#include <system_error>

#include "base/errors/input_error.h"
#include "base/scene/scene_parser.h"
#include "base/scene/text_fields.h"

namespace raystep::scene_parsing {

// The image `file` read with `wrap`, as an index in Scene::textures: a file named twice with one
// wrap mode is kept once. The renderer reads it, and names this line where it cannot.
std::int32_t SceneParser::texture_index(const std::filesystem::path& file, WrapMode wrap) {
    for (std::size_t t = 0; t < scene_.textures.size(); ++t) {
        if (scene_.textures[t].path == file.string() && scene_.textures[t].wrap == wrap)
            return static_cast<std::int32_t>(t);
    }
    scene_.textures.push_back({file.string(), wrap, static_cast<std::uint32_t>(line_)});
    return static_cast<std::int32_t>(scene_.textures.size() - 1);
}

// The image file of field k for a material's map, resolved against the scene's folder, with the
// wrap mode of field `wrap_field` (repeat when absent). The file must be there.
std::int32_t SceneParser::texture_file(std::size_t k, std::size_t wrap_field) {
    std::filesystem::path file{std::string(fields_[k])};
    if (file.is_relative()) file = folder_ / file;
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) {
        fail("image file " + quoted_field(fields_[k]) + " not found (looked for " +
             quoted_field(file.string()) + ")");
    }
    const WrapMode wrap = fields_.size() > wrap_field
                              ? static_cast<WrapMode>(keyword(wrap_field, "repeat|clamp|mirror"))
                              : WrapMode::repeat;
    return texture_index(file, wrap);
}

// `texture FILE [wrap]`, `normalmap FILE [wrap]`: the map of the objects that follow, until
// `texture off` (`normalmap off`).
void SceneParser::set_map(std::int32_t Material::*map) {
    if (fields_[1] == "off") {
        if (fields_.size() > 2) fail("'" + std::string(fields_[0]) + " off' takes nothing more");
        material_.*map = -1;
    } else {
        material_.*map = texture_file(1, 2);
    }
    material_id_ = kUnregistered;
}

void SceneParser::texture() {
    set_map(&Material::diffuse_map);
}

void SceneParser::normalmap() {
    set_map(&Material::normal_map);
    if (material_.normal_map >= 0) material_.bump_map = -1;
}

// `bumpmap FILE SCALE [wrap]`: heights of SCALE scene units at the image's value 1; a bump map
// and a normal map both tilt the normal, so one replaces the other.
void SceneParser::bumpmap() {
    if (fields_[1] == "off") {
        if (fields_.size() > 2) fail("'bumpmap off' takes nothing more");
        material_.bump_map = -1;
        material_id_ = kUnregistered;
        return;
    }
    if (fields_.size() < 3) fail("'bumpmap FILE' needs a scale: the height at the image's value 1");
    material_.bump_scale = number(2, "the bump's scale");
    material_.bump_map = texture_file(1, 3);
    material_.normal_map = -1;
    material_id_ = kUnregistered;
}

// `vertexuv x y z u v`: a vertex with texture coordinates, for `triuv`, numbered from 0.
void SceneParser::vertexuv() {
    uv_vertices_.push_back({vec3(1, "a coordinate"), {number(4, "u"), number(5, "v")}});
}

void SceneParser::triuv() {
    const auto [i0, i1, i2] = indices(uv_vertices_.size(), "vertexuvs");
    SceneTriangle triangle;
    triangle.shape = {uv_vertices_[i0].first, uv_vertices_[i1].first, uv_vertices_[i2].first};
    triangle.attributes = attributes();
    triangle.vertex_uvs = static_cast<std::int32_t>(scene_.vertex_uvs.size());
    scene_.vertex_uvs.push_back(
        {uv_vertices_[i0].second, uv_vertices_[i1].second, uv_vertices_[i2].second});
    scene_.triangles.push_back(triangle);
}

}  // namespace raystep::scene_parsing
