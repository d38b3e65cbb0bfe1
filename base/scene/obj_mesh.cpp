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

// tinyobjloader reads what it can and says little: "v 1 abc 3" becomes (1, 0, 3), "f 1 2" is
// dropped, and an index past 2^31 wraps. Before it loads, every line it will use ("v" and "f")
// is checked here, so that a bad file is an error at its line instead of a wrong mesh.
void check_obj_lines(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name, 0, "cannot open the mesh file");

    long vertices = 0;
    long largest_index = 0;
    int largest_index_line = 0;
    std::string text;
    std::vector<std::string_view> fields;
    for (int line = 1; std::getline(in, text); ++line) {
        split_fields(text, fields);
        if (fields.empty()) continue;
        const TextPosition where{name, line};
        if (fields[0] == "v") {
            if (fields.size() < 4) {
                throw InputError(name, line,
                                 "a vertex needs 3 coordinates, this one has " +
                                     std::to_string(fields.size() - 1));
            }
            for (std::size_t k = 1; k < fields.size(); ++k) {
                parse_finite_number(fields[k], where, "a vertex coordinate");
            }
            ++vertices;
        } else if (fields[0] == "f") {
            if (fields.size() < 4) {
                throw InputError(name, line,
                                 "a face needs at least 3 vertices, this one has " +
                                     std::to_string(fields.size() - 1));
            }
            for (std::size_t k = 1; k < fields.size(); ++k) {
                // A corner is v, v/vt, v//vn or v/vt/vn; v counts from 1, or back from the last
                // vertex when negative.
                std::string_view corner = fields[k].substr(0, fields[k].find('/'));
                const bool relative = !corner.empty() && corner[0] == '-';
                if (relative) corner.remove_prefix(1);
                const long index = parse_count(corner, where, "a face's vertex index");
                if (index == 0 || (relative && index > vertices)) {
                    throw InputError(name, line,
                                     "vertex index " + std::string(fields[k]) +
                                         " is out of range: OBJ counts vertices from 1, and " +
                                         std::to_string(vertices) + " are defined so far");
                }
                if (!relative && index > largest_index) {
                    largest_index = index;
                    largest_index_line = line;
                }
            }
        }
    }
    if (largest_index > vertices) {
        throw InputError(name, largest_index_line,
                         "vertex index " + std::to_string(largest_index) +
                             " is out of range: the file has " + std::to_string(vertices) +
                             " vertices, counted from 1");
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

    std::vector<std::uint32_t> polygon;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        std::size_t first = 0;
        for (const unsigned int corners : shape.mesh.num_face_vertices) {
            polygon.clear();
            for (std::size_t c = 0; c < corners; ++c) {
                polygon.push_back(
                    static_cast<std::uint32_t>(shape.mesh.indices[first + c].vertex_index));
            }
            append_triangle_fan(mesh, polygon);
            first += corners;
        }
    }
    return mesh;
}

}  // namespace raystep
