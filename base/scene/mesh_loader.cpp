#include "base/scene/mesh_loader.h"

#include <cctype>
#include <string>

#include <glm/geometric.hpp>

#include "base/errors/input_error.h"

namespace raystep {

void append_triangle_fan(TriangleMesh& mesh, const std::vector<std::uint32_t>& polygon) {
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
        mesh.faces.push_back({polygon[0], polygon[k], polygon[k + 1]});
    }
}

std::vector<Vec3> area_weighted_normals(const TriangleMesh& mesh) {
    std::vector<Vec3> normals(mesh.positions.size(), Vec3(0.0));
    for (const auto& face : mesh.faces) {
        const Vec3& p0 = mesh.positions[face[0]];
        const Vec3 normal = glm::cross(mesh.positions[face[1]] - p0, mesh.positions[face[2]] - p0);
        for (const std::uint32_t corner : face)
            normals[corner] += normal;
    }
    return normals;
}

TriangleMesh load_mesh(const std::filesystem::path& path) {
    std::error_code error;
    // Not a directory, a FIFO or a device such as /dev/zero, which could block or never end.
    if (!std::filesystem::is_regular_file(path, error)) {
        throw InputError(path.string(), 0, "not a regular file");
    }
    std::string extension = path.extension().string();
    for (char& c : extension)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".obj") return load_obj_mesh(path);
    if (extension == ".off") return load_off_mesh(path);
    throw InputError(path.string(), 0,
                     "unknown mesh format '" + extension + "': raystep reads .obj and .off");
}

}  // namespace raystep
