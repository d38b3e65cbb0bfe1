#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "base/image/wrap_mode.h"
#include "base/math/types.h"

namespace raystep {

/// The index of a face corner that names no vertex normal (or no texture coordinates).
inline constexpr std::uint32_t kNoCorner = 0xffffffffu;

/// An image a mesh material maps, and what it reads beyond its edges (MTL's `-clamp on`: clamp).
struct MeshMap {
    std::filesystem::path file;  ///< empty: no map
    WrapMode wrap = WrapMode::repeat;
};

/// A material of an OBJ file's MTL library, as far as a mesh renders it (docs/scene-format.md,
/// "Meshes"): its diffuse colour and its maps, each image's path resolved against the OBJ file's
/// folder.
struct MeshMaterial {
    std::string name;
    Color diffuse{0.0};       ///< Kd
    MeshMap diffuse_map;      ///< map_Kd
    MeshMap bump_map;         ///< map_Bump, or bump
    double bump_scale = 1.0;  ///< the bump map's -bm: the height at the image's value 1
    MeshMap normal_map;       ///< norm
};

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
    /// The materials of an OBJ file's `mtllib`, and each face's index into them (`usemtl`): one
    /// entry per face, -1 for a face before any `usemtl`; both empty for a file with none.
    std::vector<MeshMaterial> materials;
    std::vector<std::int32_t> face_materials;
};

/// Reads an OBJ or OFF file, chosen by its extension, and an OBJ file's MTL libraries. Throws
/// InputError naming the mesh file (and the line, where the reader knows it) when the file is
/// missing or malformed, has a face index out of range or a coordinate that is not finite, or
/// names a material library, a material or a map image that is not there.
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
