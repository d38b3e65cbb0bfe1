#include <cmath>
#include <fstream>
#include <string>
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

// tinyobjloader reads what it can and says little: "v 1 abc 3" becomes (1, 0, 3), "f 1 2" is
// dropped, and an index past 2^31 wraps. Before it loads, every line it will use ("v", "vn" and
// "f") is checked here, so that a bad file is an error at its line instead of a wrong mesh.
void check_obj_lines(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name, 0, "cannot open the mesh file");

    IndexedElements vertices{"vertex", "vertices"};
    IndexedElements uvs{"texture coordinate", "texture coordinates"};
    IndexedElements normals{"vertex normal", "vertex normals"};
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
        } else if (fields[0] == "f") {
            if (fields.size() < 4) {
                throw InputError(name, line,
                                 "a face needs at least 3 vertices, this one has " +
                                     std::to_string(fields.size() - 1));
            }
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

}  // namespace

TriangleMesh load_obj_mesh(const std::filesystem::path& path) {
    check_obj_lines(path);

    const std::string name = path.string();
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;  // polygons are fanned below, the same way as for OFF
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(name, config)) {
        throw InputError(name, 0, reader.Error().empty() ? "cannot read OBJ file" : reader.Error());
    }

    TriangleMesh mesh;
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
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        std::size_t first = 0;
        for (const unsigned int corners : shape.mesh.num_face_vertices) {
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
            first += corners;
        }
    }
    return mesh;
}

}  // namespace raystep
