#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <tiny_obj_loader.h>

#include "base/errors/input_error.h"
#include "base/scene/mesh_loader.h"
#include "base/scene/text_fields.h"

namespace raystep {

namespace {

// One kind of element an OBJ face indexes (positions, normals): how many the file has defined so
// far, and its largest absolute index, checked against the count at the end of the file.
struct IndexedElements {
    const char* what;    ///< "vertex", "vertex normal"
    const char* plural;  ///< "vertices", "vertex normals"
    long defined = 0;
    long largest_index = 0;
    int largest_index_line = 0;
};

// A face corner's index `field` into `elements`: from 1, or back from the last one defined
// when negative.
void check_corner_index(std::string_view field, std::string_view corner, IndexedElements& elements,
                        const TextPosition& where) {
    const bool relative = !field.empty() && field[0] == '-';
    if (relative) field.remove_prefix(1);
    const long index =
        parse_count(field, where, std::string("a face's ") + elements.what + " index");
    if (index == 0 || (relative && index > elements.defined)) {
        throw InputError(where.file, where.line,
                         std::string(elements.what) + " index " + std::string(corner) +
                             " is out of range: OBJ counts " + elements.plural + " from 1, and " +
                             std::to_string(elements.defined) + " are defined so far");
    }
    if (!relative && index > elements.largest_index) {
        elements.largest_index = index;
        elements.largest_index_line = where.line;
    }
}

// A line of finite numbers after its keyword, at least 3: a position or a normal. Its first 3.
Vec3 read_triple(const std::vector<std::string_view>& fields, const char* what,
                 const TextPosition& where) {
    if (fields.size() < 4) {
        throw InputError(where.file, where.line,
                         std::string("a ") + what + " needs 3 coordinates, this one has " +
                             std::to_string(fields.size() - 1));
    }
    Vec3 triple;
    for (std::size_t k = 1; k < fields.size(); ++k) {
        const double value =
            parse_finite_number(fields[k], where, std::string("a ") + what + " coordinate");
        if (k <= 3) triple[static_cast<int>(k - 1)] = value;
    }
    return triple;
}

// A `usemtl` line: the material it names.
struct MaterialUse {
    std::string material;
    int line = 0;
};

// What the check of an OBJ file's lines leaves for after tinyobjloader has read it: whether it
// names a material library, each `usemtl`, and for each face in file order the `usemtl` it
// follows (an index into `uses`, -1 before any).
struct ObjMaterialLines {
    bool has_library = false;
    std::vector<MaterialUse> uses;
    std::vector<int> face_use;
};

// tinyobjloader keeps a face's corner count in an unsigned char.
constexpr std::size_t kMostFaceCorners = 255;

// tinyobjloader reads what it can and says little: "v 1 abc 3" becomes (1, 0, 3), "f 1 2" is
// dropped, an index past 2^31 wraps, a face of 256 corners has 0, and a missing material library
// or material is a warning. Before it loads, every line it will use ("v", "vt", "vn", "f",
// "mtllib", "usemtl") is checked here, so that a bad file is an error at its line instead of a
// wrong mesh. A name is one word, as tinyobjloader reads it, and a library lies beside the file,
// where it looks.
ObjMaterialLines check_obj_lines(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name, 0, "cannot open the mesh file");

    IndexedElements vertices{"vertex", "vertices"};
    IndexedElements uvs{"texture coordinate", "texture coordinates"};
    IndexedElements normals{"vertex normal", "vertex normals"};
    ObjMaterialLines materials;
    std::string text;
    std::vector<std::string_view> fields;
    for (int line = 1; std::getline(in, text); ++line) {
        split_fields(text, fields);
        if (fields.empty()) continue;
        const TextPosition where{name, line};
        if (fields[0] == "v") {
            read_triple(fields, "vertex", where);
            ++vertices.defined;
        } else if (fields[0] == "vt") {
            if (fields.size() < 3) {
                throw InputError(name, line,
                                 "texture coordinates need u and v, this line has " +
                                     std::to_string(fields.size() - 1) + " numbers");
            }
            for (std::size_t k = 1; k < fields.size(); ++k) {
                parse_finite_number(fields[k], where, "a texture coordinate");
            }
            ++uvs.defined;
        } else if (fields[0] == "vn") {
            if (read_triple(fields, "vertex normal", where) == Vec3(0.0)) {
                throw InputError(name, line, "a vertex normal is zero: it has no direction");
            }
            ++normals.defined;
        } else if (fields[0] == "mtllib" || fields[0] == "usemtl") {
            if (fields.size() != 2) {
                throw InputError(name, line,
                                 "'" + std::string(fields[0]) + "' takes one name, of one word; " +
                                     "this line has " + std::to_string(fields.size() - 1));
            }
            const std::string named(fields[1]);
            if (fields[0] == "usemtl") {
                materials.uses.push_back({named, line});
                continue;
            }
            const std::filesystem::path library = path.parent_path() / named;
            std::error_code error;
            if (std::filesystem::path(named).has_parent_path() || named.find('\\') != named.npos) {
                throw InputError(name, line,
                                 "material library " + quoted_field(named) +
                                     " is not a file name: the library is read from beside the "
                                     "OBJ file");
            }
            if (!std::filesystem::is_regular_file(library, error)) {
                throw InputError(name, line,
                                 "material library " + quoted_field(named) +
                                     " not found (looked for " + quoted_field(library.string()) +
                                     ")");
            }
            materials.has_library = true;
        } else if (fields[0] == "f") {
            if (fields.size() < 4 || fields.size() - 1 > kMostFaceCorners) {
                throw InputError(name, line,
                                 "a face needs 3 to " + std::to_string(kMostFaceCorners) +
                                     " vertices, this one has " +
                                     std::to_string(fields.size() - 1));
            }
            materials.face_use.push_back(static_cast<int>(materials.uses.size()) - 1);
            for (std::size_t k = 1; k < fields.size(); ++k) {
                // A corner is v, v/vt, v//vn or v/vt/vn.
                const std::string_view corner = fields[k];
                const std::size_t slash = corner.find('/');
                check_corner_index(corner.substr(0, slash), corner, vertices, where);
                if (slash == std::string_view::npos) continue;
                const std::size_t second = corner.find('/', slash + 1);
                const std::string_view uv = corner.substr(slash + 1, second - slash - 1);
                if (!uv.empty()) check_corner_index(uv, corner, uvs, where);
                if (second != std::string_view::npos) {
                    check_corner_index(corner.substr(second + 1), corner, normals, where);
                }
            }
        }
    }
    for (const IndexedElements* elements : {&vertices, &uvs, &normals}) {
        if (elements->largest_index > elements->defined) {
            throw InputError(
                name, elements->largest_index_line,
                std::string(elements->what) + " index " + std::to_string(elements->largest_index) +
                    " is out of range: the file has " + std::to_string(elements->defined) + " " +
                    elements->plural + ", counted from 1");
        }
    }
    return materials;
}

// The fan of a polygon's corner indices (normals, uvs), as its positions fan: the same corners in
// the same order; all kNoCorner for a polygon with a corner that has none (tinyobjloader's -1,
// which the cast made kNoCorner).
void append_corner_fan(std::vector<std::array<std::uint32_t, 3>>& fans,
                       const std::vector<std::uint32_t>& corners) {
    bool every_corner = true;
    for (const std::uint32_t corner : corners)
        every_corner = every_corner && corner != kNoCorner;
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
        fans.push_back(every_corner
                           ? std::array<std::uint32_t, 3>{corners[0], corners[k], corners[k + 1]}
                           : std::array<std::uint32_t, 3>{kNoCorner, kNoCorner, kNoCorner});
    }
}

// A material's map: its image resolved against the OBJ file's folder, where the library lies.
MeshMap mesh_map(const std::string& image, const tinyobj::texture_option_t& option,
                 const std::filesystem::path& path) {
    if (image.empty()) return {};
    return {path.parent_path() / image, option.clamp ? WrapMode::clamp : WrapMode::repeat};
}

std::vector<MeshMaterial> mesh_materials(const std::vector<tinyobj::material_t>& read,
                                         const std::filesystem::path& path) {
    std::vector<MeshMaterial> materials;
    for (const tinyobj::material_t& m : read) {
        MeshMaterial material;
        material.name = m.name;
        material.diffuse = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
        material.diffuse_map = mesh_map(m.diffuse_texname, m.diffuse_texopt, path);
        material.bump_map = mesh_map(m.bump_texname, m.bump_texopt, path);
        material.bump_scale = m.bump_texopt.bump_multiplier;
        material.normal_map = mesh_map(m.normal_texname, m.normal_texopt, path);
        materials.push_back(std::move(material));
    }
    return materials;
}

// That the material a `usemtl` gave its faces can be rendered: each map's image is there and the
// bump's scale is finite. Checked for the materials faces use, at the first `usemtl` of each.
void check_used_material(const MeshMaterial& material, const MaterialUse& use,
                         const std::filesystem::path& path) {
    const std::pair<const MeshMap*, const char*> maps[] = {{&material.diffuse_map, "map_Kd"},
                                                           {&material.bump_map, "map_Bump"},
                                                           {&material.normal_map, "norm"}};
    for (const auto& [map, keyword] : maps) {
        std::error_code error;
        if (!map->file.empty() && !std::filesystem::is_regular_file(map->file, error)) {
            throw InputError(path.string(), use.line,
                             "material " + quoted_field(use.material) + ": its " + keyword +
                                 " image " + quoted_field(map->file.filename().string()) +
                                 " not found (looked for " + quoted_field(map->file.string()) +
                                 ")");
        }
    }
    if (!std::isfinite(material.bump_scale)) {
        throw InputError(path.string(), use.line,
                         "material " + quoted_field(use.material) +
                             ": its bump map's scale (-bm) is not a finite number");
    }
}

// The material of face `face_number` (in file order) as tinyobjloader gave it, `read_id`, held
// to the file's `usemtl` lines: a face after one must have its material, which tinyobjloader
// leaves out (-1) where the name is in no library named above that line.
std::int32_t face_material(const TriangleMesh& mesh, const ObjMaterialLines& lines,
                           std::size_t face_number, int read_id, std::vector<bool>& checked,
                           const std::filesystem::path& path) {
    if (face_number >= lines.face_use.size()) {
        throw InputError(path.string(), 0, "the OBJ reader read more faces than the file has");
    }
    const int use = lines.face_use[face_number];
    if (use < 0) return -1;
    const MaterialUse& named = lines.uses[static_cast<std::size_t>(use)];
    if (read_id < 0 || static_cast<std::size_t>(read_id) >= mesh.materials.size()) {
        throw InputError(path.string(), named.line,
                         "material " + quoted_field(named.material) +
                             " is in no material library named above this line");
    }
    const auto id = static_cast<std::size_t>(read_id);
    if (!checked[id]) {
        check_used_material(mesh.materials[id], named, path);
        checked[id] = true;
    }
    return read_id;
}

}  // namespace

TriangleMesh load_obj_mesh(const std::filesystem::path& path) {
    const ObjMaterialLines material_lines = check_obj_lines(path);

    const std::string name = path.string();
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;  // polygons are fanned below, the same way as for OFF
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(name, config)) {
        throw InputError(name, 0, reader.Error().empty() ? "cannot read OBJ file" : reader.Error());
    }

    TriangleMesh mesh;
    mesh.materials = mesh_materials(reader.GetMaterials(), path);
    const std::vector<tinyobj::real_t>& coordinates = reader.GetAttrib().vertices;
    mesh.positions.reserve(coordinates.size() / 3);
    for (std::size_t k = 0; k + 2 < coordinates.size(); k += 3) {
        mesh.positions.push_back({coordinates[k], coordinates[k + 1], coordinates[k + 2]});
    }

    const std::vector<tinyobj::real_t>& normals = reader.GetAttrib().normals;
    for (std::size_t k = 0; k + 2 < normals.size(); k += 3) {
        mesh.normals.push_back({normals[k], normals[k + 1], normals[k + 2]});
    }

    const std::vector<tinyobj::real_t>& uvs = reader.GetAttrib().texcoords;
    for (std::size_t k = 0; k + 1 < uvs.size(); k += 2) {
        mesh.uvs.push_back({uvs[k], uvs[k + 1]});
    }

    std::vector<std::uint32_t> polygon;
    std::vector<std::uint32_t> polygon_normals;
    std::vector<std::uint32_t> polygon_uvs;
    std::vector<bool> checked(mesh.materials.size(), false);
    std::size_t face_number = 0;  // in file order, as the shapes hold the faces
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        std::size_t first = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            const unsigned int corners = shape.mesh.num_face_vertices[f];
            polygon.clear();
            polygon_normals.clear();
            polygon_uvs.clear();
            for (std::size_t c = 0; c < corners; ++c) {
                const tinyobj::index_t& corner = shape.mesh.indices[first + c];
                polygon.push_back(static_cast<std::uint32_t>(corner.vertex_index));
                polygon_normals.push_back(static_cast<std::uint32_t>(corner.normal_index));
                polygon_uvs.push_back(static_cast<std::uint32_t>(corner.texcoord_index));
            }
            append_triangle_fan(mesh, polygon);
            if (!mesh.normals.empty()) append_corner_fan(mesh.face_normals, polygon_normals);
            if (!mesh.uvs.empty()) append_corner_fan(mesh.face_uvs, polygon_uvs);
            if (material_lines.has_library || !material_lines.uses.empty()) {
                mesh.face_materials.insert(
                    mesh.face_materials.end(), corners - 2,
                    face_material(mesh, material_lines, face_number, shape.mesh.material_ids[f],
                                  checked, path));
            }
            ++face_number;
            first += corners;
        }
    }
    return mesh;
}

}  // namespace raystep
