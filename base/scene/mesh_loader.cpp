#include "base/scene/mesh_loader.h"

#include <cctype>
#include <string>

#include "base/errors/input_error.h"

namespace raystep {

void append_triangle_fan(TriangleMesh& mesh, const std::vector<std::uint32_t>& polygon) {
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
        mesh.faces.push_back({polygon[0], polygon[k], polygon[k + 1]});
    }
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
