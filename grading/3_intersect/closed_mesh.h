#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "base/math/types.h"

namespace raystep {

/// A closed triangle mesh with its adjacency: the geometry for the watertight families. Every
/// edge has exactly two faces and every vertex a closed fan.
struct ClosedMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> faces;  ///< counter-clockwise seen from outside

    struct Edge {
        std::uint32_t a, b;      ///< its vertices
        std::uint32_t faces[2];  ///< the two faces that share it
    };
    std::vector<Edge> edges;
    std::vector<std::vector<std::uint32_t>> vertex_faces;  ///< the fan around each vertex
};

/// The unit icosphere: an icosahedron whose faces are split in four `levels` times, new vertices
/// pushed out onto the unit sphere. 20 * 4^levels faces, convex, closed.
ClosedMesh icosphere(int levels);

}  // namespace raystep
