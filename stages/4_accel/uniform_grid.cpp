// Stage 4: the uniform grid. Handout: docs/stage4.md.

#include "stages/4_accel/uniform_grid.h"

#include <cstdint>
#include <vector>

#include "base/errors/not_implemented.h"

namespace raystep {

// Your grid. The lecture's layout: the grid's box (the primitives' bounds, grown a little so
// that points on its faces are inside), the number of cells along each axis, the size of a cell,
// and for each cell the primitives whose boxes overlap it. Keep your own copy of the spheres and
// triangles, numbered as closest_hit does: spheres 0 to S - 1, then triangles S onwards.
// A vector per cell works; two flat arrays work better (count first, then fill): `first`, where
// each cell's ids begin in `ids`, with one more entry at the end.
struct UniformGrid::Impl {
    Aabb box;
    glm::ivec3 resolution{1};
    Vec3 cell_size{0.0};
    std::vector<std::size_t> first;
    std::vector<std::uint32_t> ids;
    std::vector<Sphere> spheres;
    std::vector<Triangle> triangles;
};

UniformGrid::UniformGrid(const PrimitiveList& primitives) : impl_(std::make_unique<Impl>()) {
    // 1. The box of all spheres and triangles (bounds_of in aabb.h), grown a little.
    // 2. The resolution: grid_resolution(box, number of primitives).
    // 3. Enter each primitive in every cell its box overlaps: the cells from the one holding the
    //    box's min corner to the one holding its max corner, along each axis,
    //      cell = clamp(floor((x - box.min) / cell_size), 0, resolution - 1).
    RAYSTEP_TODO(4, "UniformGrid::UniformGrid", "Uniform grids");
}

UniformGrid::~UniformGrid() = default;
UniformGrid::UniformGrid(UniformGrid&&) noexcept = default;
UniformGrid& UniformGrid::operator=(UniformGrid&&) noexcept = default;

std::optional<PrimitiveHit> UniformGrid::closest_hit(const Ray& ray, TraversalStats* stats) const {
    // Clip the ray to the grid's box with intersect_aabb; a miss is a miss. Start in the cell
    // holding the ray's point at the entry t (clamped into the grid). Then, per axis:
    //   stepX  = +1 or -1, the sign of D.x (0 when D.x = 0: never step along x)
    //   tMaxX  = t at which the ray crosses the next plane between cells along x
    //   tDelta = cell size / |D.x|, how much t grows from one such plane to the next
    // Loop: test the cell's primitives (each once per ray, even if it is in many cells: a
    // mailbox), keep the best by comes_before with t_max cut to it; then step along the axis
    // with the smallest tMax (cell += step, tMax += tDelta). Stop when the ray leaves the grid,
    // or when the next cell begins (the smallest tMax) beyond the best hit, not before: a hit
    // found in this cell may lie in the next, and rounding may put it just past this cell's exit.
    RAYSTEP_TODO(4, "UniformGrid::closest_hit", "Walking the grid (3D-DDA)");
}

bool UniformGrid::occluded(const Ray& ray, TraversalStats* stats) const {
    // The same walk, stopping at the first hit in [t_min, t_max].
    RAYSTEP_TODO(4, "UniformGrid::occluded", "Walking the grid (3D-DDA)");
}

glm::ivec3 UniformGrid::resolution() const {
    // The cells along x, y and z that the constructor chose.
    RAYSTEP_TODO(4, "UniformGrid::resolution", "Uniform grids");
}

UniformGridData UniformGrid::cells() const {
    // Your grid as the grader reads it: the box, the resolution, and each cell's primitive
    // numbers (spheres first, then triangles), the cells x fastest, then y, then z: with the two
    // flat arrays above, cell c lists ids[first[c] .. first[c + 1]).
    RAYSTEP_TODO(4, "UniformGrid::cells", "Handing the structure over");
}

glm::ivec3 grid_resolution(const Aabb& bounds, std::size_t n) {
    // About c n cells in all (c = kCellsPerPrimitive), as near to cubes as whole numbers allow:
    //   k = cbrt(c n / V), V = the box's volume      cells along an axis = round(extent * k)
    // clamped to [1, 256]. An axis with no extent (a flat scene) gets 1 cell and the others
    // share the c n cells: k = sqrt(c n / area). The handout has the rest.
    RAYSTEP_TODO(4, "grid_resolution", "Grid resolution");
}

}  // namespace raystep
