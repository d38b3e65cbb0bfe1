#include <cmath>
#include <string>

#include <tiny_obj_loader.h>

#include "core/errors/input_error.h"
#include "core/scene/mesh_loader.h"

namespace raystep {

TriangleMesh load_obj_mesh(const std::filesystem::path& path) {
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
        const Vec3 p{coordinates[k], coordinates[k + 1], coordinates[k + 2]};
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw InputError(
                name, 0, "vertex " + std::to_string(k / 3 + 1) + " has a non-finite coordinate");
        }
        mesh.positions.push_back(p);
    }

    std::vector<std::uint32_t> polygon;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        std::size_t first = 0;
        for (const unsigned int corners : shape.mesh.num_face_vertices) {
            polygon.clear();
            for (std::size_t c = 0; c < corners; ++c) {
                const int index = shape.mesh.indices[first + c].vertex_index;
                if (index < 0 || static_cast<std::size_t>(index) >= mesh.positions.size()) {
                    throw InputError(name, 0,
                                     "a face of '" + shape.name + "' uses vertex " +
                                         std::to_string(index + 1) + ", but the file has " +
                                         std::to_string(mesh.positions.size()) + " vertices");
                }
                polygon.push_back(static_cast<std::uint32_t>(index));
            }
            append_triangle_fan(mesh, polygon);
            first += corners;
        }
    }
    return mesh;
}

}  // namespace raystep
