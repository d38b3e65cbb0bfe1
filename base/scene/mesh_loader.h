#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "base/math/types.h"

namespace raystep {

/// An indexed triangle mesh as read from a file; polygons are split into triangle fans
/// (i0 i1 i2, i0 i2 i3, ...), which is exact for the convex faces these formats hold.
struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<std::array<std::uint32_t, 3>> faces;
};

/// Reads an OBJ or OFF file, chosen by its extension. Throws InputError naming the mesh file
/// (and the line, where the reader knows it) when the file is missing or malformed, or has a face
/// index out of range or a coordinate that is not finite.
TriangleMesh load_mesh(const std::filesystem::path& path);

/// Adds the polygon's fan (i0 i1 i2, i0 i2 i3, ...) to the mesh's faces.
void append_triangle_fan(TriangleMesh& mesh, const std::vector<std::uint32_t>& polygon);

/// The readers behind load_mesh, one per format.
TriangleMesh load_obj_mesh(const std::filesystem::path& path);
TriangleMesh load_off_mesh(const std::filesystem::path& path);

}  // namespace raystep
