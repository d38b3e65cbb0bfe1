#pragma once

// The 3D-DDA: the cells a ray passes through, in order along the ray (Amanatides and Woo 1987,
// "A Fast Voxel Traversal Algorithm for Ray Tracing", Eurographics '87; after Fujimoto, Tanaka
// and Iwata 1986, "ARTS: Accelerated Ray-Tracing System", IEEE CG&A 6(4)).

#include <algorithm>
#include <cstddef>
#include <limits>

#include "solutions/4_accel/grid_layout.h"
#include "stages/2_rays/ray.h"

namespace raystep {

/// Walks a grid's cells along a ray. Every step leaves the grid or moves one cell along one axis
/// in the direction the ray goes, so a walk ends after at most resolution.x + resolution.y +
/// resolution.z steps, whatever the numbers (NaN included).
class GridWalk {
  public:
    /// Starts in the cell that holds the ray's point at t = `enter`, the t at which the slab test
    /// says the ray is first inside the grid's box. `inverse_direction` is 1 / ray.direction.
    GridWalk(const GridLayout& grid, const Ray& ray, const Vec3& inverse_direction, double enter)
        : grid_(grid), origin_(ray.origin), inverse_(inverse_direction) {
        // The starting cell, clamped: rounding can put a point on the box's face just outside it
        const Vec3 start = ray.origin + enter * ray.direction;
        for (int axis = 0; axis < 3; ++axis) {
            cell_[axis] = grid.cell_of(start[axis], axis);
            step_[axis] = ray.direction[axis] > 0.0 ? 1 : ray.direction[axis] < 0.0 ? -1 : 0;
            next_[axis] = crossing(axis);
        }
    }

    /// The current cell's place in the cell lists.
    std::size_t cell() const { return grid_.index(cell_); }

    /// The t at which the ray leaves the current cell, which is where the next cell begins; +inf
    /// when it never does (it runs parallel to every plane it could cross). Never NaN.
    double exit() const { return std::min({next_.x, next_.y, next_.z}); }

    /// Moves into the next cell: across the plane that the ray meets first (ties: x, then y).
    /// False when that takes the walk out of the grid.
    bool step() {
        const int axis =
            next_.x <= next_.y ? (next_.x <= next_.z ? 0 : 2) : (next_.y <= next_.z ? 1 : 2);
        if (step_[axis] == 0) return false;  // all three are +inf: nothing left to cross
        cell_[axis] += step_[axis];
        if (cell_[axis] < 0 || cell_[axis] >= grid_.resolution[axis]) return false;
        next_[axis] = crossing(axis);
        return true;
    }

  private:
    // The slide's tMax: the t at which the ray crosses the next plane along `axis`. The slide
    // adds tDelta = cell size / |D| to it at each step; that sum rounds once per step, up to 256
    // times. Computed afresh from the plane, it is two roundings from the exact crossing, which
    // is what the grid's margin (uniform_grid.cpp) is sized for.
    double crossing(int axis) const {
        if (step_[axis] == 0) return kNever;
        const int plane = step_[axis] > 0 ? cell_[axis] + 1 : cell_[axis];
        const double t = (grid_.plane(axis, plane) - origin_[axis]) * inverse_[axis];
        // NaN when 1 / D overflowed for a subnormal component and the origin is on the plane: the
        // ray then stays on that plane, as with a zero component. Written to catch NaN.
        return t == t ? t : kNever;
    }

    static constexpr double kNever = std::numeric_limits<double>::infinity();

    const GridLayout& grid_;
    Vec3 origin_;
    Vec3 inverse_;
    glm::ivec3 cell_{0};
    glm::ivec3 step_{0};  ///< the slide's stepX, stepY, stepZ: +1, -1, or 0 for a zero component
    Vec3 next_{kNever};   ///< the slide's tMaxX, tMaxY, tMaxZ
};

}  // namespace raystep
