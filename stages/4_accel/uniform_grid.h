#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "stages/3_intersect/intersect.h"
#include "stages/4_accel/aabb.h"
#include "stages/4_accel/traversal.h"

namespace raystep {

/// A uniform grid as plain data (UniformGrid::cells): the grader checks a grid through it and walks
/// it with a 3D-DDA of its own.
struct UniformGridData {
    /// The grid's box: cell (i, j, k) runs from bounds.min + (i, j, k) * size to one size further,
    /// size = bounds.extent() / resolution.
    Aabb bounds;
    glm::ivec3 resolution{0};
    /// Each cell's primitives (spheres 0 to S - 1, then triangles from S), the cells in order of
    /// i + resolution.x * (j + resolution.y * k): x fastest, then y, then z.
    std::vector<std::vector<std::size_t>> cells;
};

/// A uniform grid over the spheres and triangles of a PrimitiveList (planes stay outside), walked
/// cell by cell along the ray with the 3D-DDA of Amanatides and Woo (1987). Its layout is the
/// implementation's own (UniformGrid::Impl, in uniform_grid.cpp).
class UniformGrid {
  public:
    /// Builds over a copy of the list's spheres and triangles, with the resolution of
    /// grid_resolution.
    explicit UniformGrid(const PrimitiveList& primitives);
    ~UniformGrid();
    UniformGrid(UniformGrid&&) noexcept;
    UniformGrid& operator=(UniformGrid&&) noexcept;

    /// Exactly what closest_hit returns for the same spheres and triangles (same primitive, same
    /// t, ties broken by comes_before). A primitive that spans several cells is tested once; the
    /// walk stops once no cell that could hold a nearer hit is left.
    std::optional<PrimitiveHit> closest_hit(const Ray& ray, TraversalStats* stats = nullptr) const;

    /// True when any sphere or triangle has a hit in [ray.t_min, ray.t_max].
    bool occluded(const Ray& ray, TraversalStats* stats = nullptr) const;

    /// Cells along x, y and z.
    glm::ivec3 resolution() const;

    /// The grid as data: its box, its resolution and what each cell lists, every primitive in
    /// every cell its box overlaps. docs/stage4.md, "Handing the structure over".
    UniformGridData cells() const;

    struct Impl;

  private:
    std::unique_ptr<Impl> impl_;
};

/// Cells per primitive in a uniform grid: fewer, larger cells than pbrt's (about 27 per
/// primitive), which are cheaper to build and to walk (docs/stage4.md, "Grid resolution").
inline constexpr double kCellsPerPrimitive = 3.0;

/// The most cells along one axis: 256^3 cells already take 134 MB of cell offsets.
inline constexpr int kMaxCellsPerAxis = 256;

/// The cells along each axis for n primitives in a box: about kCellsPerPrimitive n cells in all,
/// shaped like the box (cubes as near as whole numbers allow), at least 1 and at most
/// kMaxCellsPerAxis per axis; an axis too thin for a whole cell gets one, and the others share
/// the rest. docs/stage4.md, "Grid resolution", says where the numbers come from.
glm::ivec3 grid_resolution(const Aabb& bounds, std::size_t n);

}  // namespace raystep
