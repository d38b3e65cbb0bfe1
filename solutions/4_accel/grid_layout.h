#pragma once

// The reference grid's geometry: where its cells are, which cell a coordinate falls in, where the
// planes between cells lie. The cell lists (grid_cells.h) and the walk (grid_walk.h) both use it.

#include <cmath>
#include <cstddef>

#include <glm/vec3.hpp>

#include "stages/4_accel/aabb.h"

namespace raystep {

/// A box cut into resolution.x * resolution.y * resolution.z equal cells.
struct GridLayout {
    Aabb box;                  ///< the grid's box; every axis has a positive extent
    glm::ivec3 resolution{1};  ///< cells along x, y and z
    Vec3 cell_size{0.0};       ///< the box's extent / resolution, per axis
    Vec3 cells_per_unit{0.0};  ///< resolution / the box's extent, per axis

    GridLayout() = default;
    GridLayout(const Aabb& grid_box, glm::ivec3 cells)
        : box(grid_box),
          resolution(cells),
          cell_size(grid_box.extent() / Vec3(cells)),
          cells_per_unit(Vec3(cells) / grid_box.extent()) {}

    /// The cell along `axis` that holds coordinate x, clamped into the grid: a point a rounding
    /// error outside the box belongs to the nearest cell, and so does a NaN (to cell 0), so the
    /// result is always a valid index. The clamping is done in double, before the conversion to
    /// int, which for a value out of int's range would be undefined.
    int cell_of(double x, int axis) const {
        const double cell = std::floor((x - box.min[axis]) * cells_per_unit[axis]);
        if (!(cell >= 0.0)) return 0;  // also NaN
        return cell < resolution[axis] ? static_cast<int>(cell) : resolution[axis] - 1;
    }

    /// The coordinate of plane j along `axis`: plane j is the lower face of cell j, plane
    /// `resolution[axis]` the box's upper face.
    double plane(int axis, int j) const { return box.min[axis] + j * cell_size[axis]; }

    /// The cell's position in the cell lists: x varies fastest.
    std::size_t index(const glm::ivec3& cell) const {
        return (static_cast<std::size_t>(cell.z) * resolution.y + cell.y) * resolution.x + cell.x;
    }

    std::size_t cell_count() const {
        return static_cast<std::size_t>(resolution.x) * resolution.y * resolution.z;
    }
};

}  // namespace raystep
