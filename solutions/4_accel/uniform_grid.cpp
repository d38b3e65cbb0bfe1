// Stage 4 reference solution: the uniform grid. Its resolution, its cells (grid_layout.h,
// grid_cells.h), and the walk along a ray (grid_walk.h, grid_mailbox.h) that finds exactly
// closest_hit's answer.

#include "stages/4_accel/uniform_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "solutions/4_accel/grid_cells.h"
#include "solutions/4_accel/grid_layout.h"
#include "solutions/4_accel/grid_mailbox.h"
#include "solutions/4_accel/grid_walk.h"

namespace raystep {

struct UniformGrid::Impl {
    std::vector<Sphere> spheres;      ///< ids 0 to S - 1
    std::vector<Triangle> triangles;  ///< ids S to S + T - 1
    GridLayout layout;
    GridCells cells;

    std::size_t primitive_count() const { return spheres.size() + triangles.size(); }
};

namespace {

// How far beyond its box a primitive is entered in cells. Two roundings must not lose a hit that
// closest_hit finds:
// - the point A + t D of a computed hit can lie a little outside its primitive's box: t is
//   rounded, and the watertight test accepts rays within rounding of an edge;
// - the walk's crossings (grid_walk.h) are a couple of roundings off, so within rounding of a
//   plane it may place the ray in the cell beside the one the ray is in.
// Both are a few units of rounding (2^-53) of the coordinates involved: the scene's, the ray's
// origin, the hit point. The margin is 2^-20 of the grid's largest extent, which covers 32 units
// of rounding of coordinates up to 2^28 grid sizes from the origin, and at least 2^-44 of the
// largest coordinate (512 units of its rounding), for a scene small beside its distance from the
// origin. It costs little: cells are near cubes, at most 256 along the longest axis, so 2^-20
// of that axis is at most 1/4096 of a cell, and about one box face in 4096 reaches into one more
// layer of cells (the second term is larger only for a scene 2^24 of its sizes from the origin).
double cell_margin(const Aabb& bounds) {
    const Vec3 extent = bounds.extent();
    const Vec3 magnitude = glm::max(glm::abs(bounds.min), glm::abs(bounds.max));
    const double margin = std::max(0x1p-20 * std::max({extent.x, extent.y, extent.z}),
                                   0x1p-44 * std::max({magnitude.x, magnitude.y, magnitude.z}));
    // 0 only for primitives that are all one point at the origin: any box around it will do.
    return margin > 0.0 ? margin : 1.0;
}

// The hit of primitive `id`, numbered and reported as closest_hit does.
std::optional<PrimitiveHit> test_primitive(const UniformGrid::Impl& grid, std::uint32_t id,
                                           const Ray& ray) {
    if (id < grid.spheres.size()) {
        const std::optional<Hit> hit = intersect_sphere(ray, grid.spheres[id]);
        if (hit) return PrimitiveHit{*hit, PrimitiveKind::sphere, id};
        return std::nullopt;
    }
    const std::size_t index = id - grid.spheres.size();
    const std::optional<Hit> hit = intersect_triangle(ray, grid.triangles[index]);
    if (hit) return PrimitiveHit{*hit, PrimitiveKind::triangle, index};
    return std::nullopt;
}

// The walk both queries share: from the cell where the ray enters the grid, cell by cell along
// the ray, testing each primitive once. After each cell, limit() says how far the search still
// reaches; the walk stops when the next cell begins beyond it or the ray leaves the grid.
// test(id) tests a primitive and returns true to stop at once.
template <class Limit, class Test>
void walk_grid(const UniformGrid::Impl& grid, const Ray& ray, TraversalStats* stats, Limit limit,
               Test test) {
    // Nothing to visit: no primitives, no direction, or a ray that misses the grid's box
    if (grid.cells.ids.empty() || ray.direction == Vec3(0.0)) return;
    const Vec3 inverse = 1.0 / ray.direction;
    const std::optional<Interval> inside = intersect_aabb(ray, inverse, grid.layout.box);
    if (!inside) return;

    Mailbox mailbox(grid.primitive_count());
    GridWalk walk(grid.layout, ray, inverse, inside->enter);
    std::uint64_t cells = 0;
    std::uint64_t tests = 0;
    bool stopped = false;
    while (!stopped) {
        ++cells;
        const std::size_t cell = walk.cell();
        for (const std::uint32_t* id = grid.cells.begin(cell); id != grid.cells.end(cell); ++id) {
            if (!mailbox.first_visit(*id)) continue;
            ++tests;
            if (test(*id)) {
                stopped = true;
                break;
            }
        }
        // The next cell begins beyond the search's reach (at most t_max), or outside the grid.
        // Written so that a NaN stops the walk.
        if (stopped || !(walk.exit() <= limit()) || !walk.step()) break;
    }
    if (stats) {
        stats->nodes += cells;
        stats->primitive_tests += tests;
    }
}

}  // namespace

glm::ivec3 grid_resolution(const Aabb& bounds, std::size_t n) {
    glm::ivec3 cells(1);
    if (n == 0 || bounds.empty()) return cells;

    // The axes that share the cells: those with an extent
    const Vec3 extent = bounds.extent();
    bool shares[3];
    int sharing = 0;
    for (int axis = 0; axis < 3; ++axis) {
        shares[axis] = extent[axis] > 0.0 && std::isfinite(extent[axis]);
        sharing += shares[axis];
    }
    if (sharing == 0) return cells;  // a single point

    // Cells per unit length, k = (c n / V)^(1/d) over the d sharing axes, V the product of their
    // extents: axis i gets e_i k cells, and together they make c n (Cleary and Wyvill 1988; pbrt's
    // grid). In logarithms, because V can overflow or underflow where no extent does.
    // An axis too thin for one whole cell (e_i k < 1) gets one, and the others share the c n cells
    // as if the box were flat: a zero extent is the limit case. Otherwise a box 4 x 4 x 1e-9 would
    // need cells 1e-9 wide to make them cubes, and get 256 x 256 x 1 of them for a few triangles.
    // Taking an axis out lowers k, so an axis never comes back; the longest one never goes, as
    // e_max k >= (c n)^(1/d) >= 1.
    const double log_total = std::log(kCellsPerPrimitive * static_cast<double>(n));
    double log_k = 0.0;
    for (bool thinned = true; thinned;) {
        int d = 0;
        double log_volume = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            if (!shares[axis]) continue;
            ++d;
            log_volume += std::log(extent[axis]);
        }
        log_k = (log_total - log_volume) / d;
        thinned = false;
        for (int axis = 0; axis < 3; ++axis) {
            if (shares[axis] && std::log(extent[axis]) + log_k < 0.0) {
                shares[axis] = false;
                thinned = true;
            }
        }
    }

    // Whole numbers of cells, at least 1 and at most the cap, clamped before converting to int
    for (int axis = 0; axis < 3; ++axis) {
        if (!shares[axis]) continue;
        const double exact = std::exp(std::log(extent[axis]) + log_k);
        cells[axis] = static_cast<int>(
            std::clamp(std::round(exact), 1.0, static_cast<double>(kMaxCellsPerAxis)));
    }
    return cells;
}

UniformGrid::UniformGrid(const PrimitiveList& primitives) : impl_(std::make_unique<Impl>()) {
    Impl& grid = *impl_;
    grid.spheres = primitives.spheres;
    grid.triangles = primitives.triangles;
    const std::size_t n = grid.primitive_count();
    if (n > std::numeric_limits<std::uint32_t>::max()) {
        throw std::length_error("UniformGrid: " + std::to_string(n) +
                                " primitives, more than its 32-bit ids can number");
    }

    // Each primitive's box, in id order, and the box of them all. A triangle is entered in every
    // cell its box overlaps, not only those the triangle itself cuts: a long thin diagonal
    // triangle sits in cells it misses, which costs tests but never a hit. An exact
    // triangle-box test (Akenine-Möller 2001) would prune those, at a cost in building and in
    // the care its own rounding needs.
    std::vector<Aabb> boxes;
    boxes.reserve(n);
    for (const Sphere& sphere : grid.spheres)
        boxes.push_back(bounds_of(sphere));
    for (const Triangle& triangle : grid.triangles)
        boxes.push_back(bounds_of(triangle));
    Aabb bounds;
    for (const Aabb& box : boxes)
        bounds.add(box);
    if (bounds.empty()) return;  // no primitives: no cells, and every query finds nothing

    // The grid's box is the bounds grown by the margin, so that it holds every hit point that
    // the margin allows for
    const double margin = cell_margin(bounds);
    grid.layout = GridLayout({bounds.min - Vec3(margin), bounds.max + Vec3(margin)},
                             grid_resolution(bounds, n));
    grid.cells = fill_cells(grid.layout, boxes, margin);
}

UniformGrid::~UniformGrid() = default;
UniformGrid::UniformGrid(UniformGrid&&) noexcept = default;
UniformGrid& UniformGrid::operator=(UniformGrid&&) noexcept = default;

std::optional<PrimitiveHit> UniformGrid::closest_hit(const Ray& ray, TraversalStats* stats) const {
    // Every primitive is tested with t_max cut to the best t so far, as closest_hit does, and the
    // best kept by comes_before: the same answer, found in another order.
    //
    // When to stop: the walk goes on while the next cell begins at or before the best t. A hit
    // found in one cell may lie in a later one, and a primitive of the next cell may still tie
    // with it. Accepting a hit only if it lies within the current cell, and stopping at the
    // first, loses hits: with mailboxing, a primitive whose hit lies in a later cell is rejected
    // here and never tested again; without, a hit that rounds just past the exit of the last
    // cell listing its primitive is rejected there and found nowhere. No slack in t is needed:
    // a primitive with t <= best is listed in the cell the walk is in at that t, because the
    // margin covers both the hit point's rounding and the walk's (cell_margin).
    Ray nearer = ray;
    std::optional<PrimitiveHit> best;
    walk_grid(
        *impl_, ray, stats, [&] { return nearer.t_max; },
        [&](std::uint32_t id) {
            const std::optional<PrimitiveHit> hit = test_primitive(*impl_, id, nearer);
            if (hit && (!best || comes_before(*hit, *best))) {
                best = hit;
                nearer.t_max = hit->hit.t;
            }
            return false;
        });
    return best;
}

bool UniformGrid::occluded(const Ray& ray, TraversalStats* stats) const {
    bool found = false;
    walk_grid(
        *impl_, ray, stats, [&] { return ray.t_max; },
        [&](std::uint32_t id) { return found = test_primitive(*impl_, id, ray).has_value(); });
    return found;
}

glm::ivec3 UniformGrid::resolution() const {
    return impl_->layout.resolution;
}

UniformGridData UniformGrid::cells() const {
    UniformGridData data;
    data.bounds = impl_->layout.box;
    data.resolution = impl_->layout.resolution;
    data.cells.resize(impl_->layout.cell_count());
    for (std::size_t cell = 0; cell < data.cells.size(); ++cell)
        data.cells[cell].assign(impl_->cells.begin(cell), impl_->cells.end(cell));
    return data;
}

}  // namespace raystep
