#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "base/math/types.h"

namespace raystep {

/// The index of a face corner that names no vertex normal (or no texture coordinates).
inline constexpr std::uint32_t kNoCorner = 0xffffffffu;

/// An indexed triangle mesh as read from a file; polygons are split into triangle fans
/// (i0 i1 i2, i0 i2 i3, ...), which is exact for the convex faces these formats hold.
struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<std::array<std::uint32_t, 3>> faces;
    /// The file's vertex normals (OBJ's `vn`), as written, not normalized; empty for a file that
    /// has none.
    std::vector<Vec3> normals;
    /// Each face's corners' indices into `normals`, one entry per face, or empty where the file
    /// has no normals. A face whose corners do not all name one has kNoCorner in each.
    std::vector<std::array<std::uint32_t, 3>> face_normals;
    /// The file's texture coordinates (OBJ's `vt`), and each face's corners' indices into them,
    /// as `normals` and `face_normals` are: kNoCorner where a corner names none.
    std::vector<Vec2> uvs;
    std::vector<std::array<std::uint32_t, 3>> face_uvs;
};

/// Reads an OBJ or OFF file, chosen by its extension. Throws InputError naming the mesh file
/// (and the line, where the reader knows it) when the file is missing or malformed, or has a face
/// index out of range or a coordinate that is not finite.
TriangleMesh load_mesh(const std::filesystem::path& path);

/// Adds the polygon's fan (i0 i1 i2, i0 i2 i3, ...) to the mesh's faces.
void append_triangle_fan(TriangleMesh& mesh, const std::vector<std::uint32_t>& polygon);

/// A normal for each position, for a mesh shaded smooth that brings none (`mesh FILE smooth`):
/// the sum of the geometric normals (p1 - p0) x (p2 - p0) of the faces around it, so each face
/// weighs by its area. Not normalized; zero at a position no face with area uses.
std::vector<Vec3> area_weighted_normals(const TriangleMesh& mesh);

/// The readers behind load_mesh, one per format.
TriangleMesh load_obj_mesh(const std::filesystem::path& path);
TriangleMesh load_off_mesh(const std::filesystem::path& path);

}  // namespace raystep
