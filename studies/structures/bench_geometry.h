#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "base/scene/mesh_loader.h"
#include "base/scene/shapes.h"

namespace raystep {

// The bench's scenes, made from a mesh file or from a seed. Seeded scenes are the same on every
// platform (base/math/portable_random.h).

/// The mesh's faces as triangles, in face order.
std::vector<Triangle> mesh_triangles(const TriangleMesh& mesh);

/// columns x rows copies of the triangles side by side along x (columns) and z (rows), each
/// copy shifted from the last by `spacing` times the triangles' extent along that axis; copy
/// after copy, each in the triangles' order.
std::vector<Triangle> tiled_copies(const std::vector<Triangle>& triangles, int columns, int rows,
                                   double spacing);

/// `count` spheres with centres uniform in the unit cube [0, 1]^3 and radii uniform in
/// [0.25, 0.75] s, s = count^(-1/3) the cube's side divided among them: a cloud dense enough that
/// most rays into it hit something.
std::vector<Sphere> random_spheres(std::size_t count, std::uint64_t seed);

/// `count` triangles, each with its vertices uniform in a cube of side s = count^(-1/3) around a
/// centre uniform in the unit cube: the same density of stuff for every count.
std::vector<Triangle> random_triangles(std::size_t count, std::uint64_t seed);

}  // namespace raystep
