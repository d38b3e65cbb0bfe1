// Stage 4: the uniform grid. Handout: docs/stage4.md, "Uniform grids", "Grid resolution" and
// "Walking the grid (3D-DDA)".

#include "stages/4_accel/uniform_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace raystep {

// The grid's box, its cells, and each cell's primitives in two flat arrays: cell c holds
// ids[first[c]] to ids[first[c + 1] - 1]. Ids are closest_hit's numbers: spheres 0 to S - 1,
// then triangles from S.
struct UniformGrid::Impl {
    Aabb box;
    glm::ivec3 resolution{1};
    Vec3 cell_size{0.0};
    Vec3 cells_per_unit{0.0};
    std::vector<std::size_t> first;
    std::vector<std::uint32_t> ids;
    std::vector<Sphere> spheres;
    std::vector<Triangle> triangles;

    // The cell along `axis` that holds coordinate x, clamped into the grid in double before
    // converting to int (a NaN goes to cell 0).
    int cell_of(double x, int axis) const {
        const double cell = std::floor((x - box.min[axis]) * cells_per_unit[axis]);
        if (!(cell >= 0.0)) return 0;
        return cell < resolution[axis] ? static_cast<int>(cell) : resolution[axis] - 1;
    }

    // Plane j along `axis`: the lower face of cell j.
    double plane(int axis, int j) const { return box.min[axis] + j * cell_size[axis]; }

    std::size_t index(const glm::ivec3& cell) const {
        return (static_cast<std::size_t>(cell.z) * resolution.y + cell.y) * resolution.x + cell.x;
    }
};

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// How far beyond its box a primitive is entered in cells. A computed hit point can lie a few
// roundings outside its primitive's box, and the walk's plane crossings are a couple of
// roundings off, so near a plane between cells it may think the ray is in the neighbouring
// cell. Both are a few units of 2^-53 of the coordinates: 2^-20 of the grid's size (and at
// least 2^-44 of its largest coordinate, for a scene far from the origin) covers them with room
// to spare, and is at most 1/4096 of a cell. With it, a primitive whose hit is at t is listed in
// the cell the walk is in at t, and the walk can stop as soon as the next cell begins beyond the
// best hit.
double cell_margin(const Aabb& bounds) {
    const Vec3 extent = bounds.extent();
    const Vec3 magnitude = glm::max(glm::abs(bounds.min), glm::abs(bounds.max));
    const double margin = std::max(0x1p-20 * std::max({extent.x, extent.y, extent.z}),
                                   0x1p-44 * std::max({magnitude.x, magnitude.y, magnitude.z}));
    return margin > 0.0 ? margin : 1.0;  // 0 only for a scene that is one point at the origin
}

std::optional<PrimitiveHit> test_primitive(const UniformGrid::Impl& grid, std::uint32_t id, const Ray& ray) {
    if (id < grid.spheres.size()) {
        if (const std::optional<Hit> hit = intersect_sphere(ray, grid.spheres[id])) {
            return PrimitiveHit{*hit, PrimitiveKind::sphere, id};
        }
        return std::nullopt;
    }
    const std::size_t index = id - grid.spheres.size();
    if (const std::optional<Hit> hit = intersect_triangle(ray, grid.triangles[index])) {
        return PrimitiveHit{*hit, PrimitiveKind::triangle, index};
    }
    return std::nullopt;
}

// The 3D-DDA of Amanatides and Woo (1987), shared by both queries: the cells along the ray in
// order, each primitive tested once (a mailbox of the ids tested in this query). After each cell
// the walk goes on only while the next cell begins at or before limit(): a hit found in one
// cell may lie in a later one, and a primitive of the next cell may still tie with it.
// test(id) returns true to stop at once.
template <class Limit, class Test>
void walk(const UniformGrid::Impl& grid, const Ray& ray, TraversalStats* stats, Limit limit, Test test) {
    // Nothing to visit: no primitives, no direction, or a ray that misses the grid's box
    if (grid.ids.empty() || ray.direction == Vec3(0.0)) return;
    const Vec3 inverse = 1.0 / ray.direction;
    const std::optional<Interval> inside = intersect_aabb(ray, inverse, grid.box);
    if (!inside) return;

    // Start in the cell that holds the point where the ray enters the grid (clamped: rounding
    // can put it just outside)
    const Vec3 start = ray.at(inside->enter);
    glm::ivec3 cell;
    glm::ivec3 step;
    Vec3 next;  // the slide's tMax: where the ray crosses the next plane along each axis
    // The crossing is computed afresh from the plane's coordinate rather than by adding tDelta
    // at each step, which would round once per step. A zero component never crosses (inf).
    const auto crossing = [&](int axis) {
        if (step[axis] == 0) return kInfinity;
        const int plane = step[axis] > 0 ? cell[axis] + 1 : cell[axis];
        const double t = (grid.plane(axis, plane) - ray.origin[axis]) * inverse[axis];
        return t == t ? t : kInfinity;  // NaN: the ray runs along that plane
    };
    for (int axis = 0; axis < 3; ++axis) {
        cell[axis] = grid.cell_of(start[axis], axis);
        step[axis] = ray.direction[axis] > 0.0 ? 1 : (ray.direction[axis] < 0.0 ? -1 : 0);
    }
    for (int axis = 0; axis < 3; ++axis) next[axis] = crossing(axis);

    std::vector<std::uint32_t> tested;
    for (;;) {
        if (stats) ++stats->nodes;
        const std::size_t c = grid.index(cell);
        for (std::size_t k = grid.first[c]; k < grid.first[c + 1]; ++k) {
            const std::uint32_t id = grid.ids[k];
            if (std::find(tested.begin(), tested.end(), id) != tested.end()) continue;
            tested.push_back(id);
            if (stats) ++stats->primitive_tests;
            if (test(id)) return;
        }
        // Across the plane the ray meets first (ties: x, then y). Stop when that next cell
        // begins beyond the search's reach (written so that NaN stops), or is outside the grid.
        const int axis = next.x <= next.y ? (next.x <= next.z ? 0 : 2) : (next.y <= next.z ? 1 : 2);
        if (!(next[axis] <= limit())) return;
        if (step[axis] == 0) return;  // every crossing is infinite: nothing left to cross
        cell[axis] += step[axis];
        if (cell[axis] < 0 || cell[axis] >= grid.resolution[axis]) return;
        next[axis] = crossing(axis);
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
        sharing += shares[axis] ? 1 : 0;
    }
    if (sharing == 0) return cells;  // a single point

    // k = (c n / V)^(1/d), cells per unit length over the d sharing axes, in logarithms: V is a
    // product of extents and can overflow or underflow where no extent does. An axis too thin
    // for a whole cell (e k < 1) gets one and the others share the cells; that lowers k, so
    // check again.
    const double log_cells = std::log(kCellsPerPrimitive * static_cast<double>(n));
    double log_k = 0.0;
    for (bool thinned = true; thinned;) {
        int d = 0;
        double log_volume = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            if (!shares[axis]) continue;
            ++d;
            log_volume += std::log(extent[axis]);
        }
        log_k = (log_cells - log_volume) / d;
        thinned = false;
        for (int axis = 0; axis < 3; ++axis) {
            if (shares[axis] && std::log(extent[axis]) + log_k < 0.0) {
                shares[axis] = false;
                thinned = true;
            }
        }
    }

    // round(e k), clamped to [1, 256] in double before converting to int
    for (int axis = 0; axis < 3; ++axis) {
        if (!shares[axis]) continue;
        const double exact = std::exp(std::log(extent[axis]) + log_k);
        cells[axis] = static_cast<int>(std::clamp(std::round(exact), 1.0, static_cast<double>(kMaxCellsPerAxis)));
    }
    return cells;
}

UniformGrid::UniformGrid(const PrimitiveList& primitives) : impl_(std::make_unique<Impl>()) {
    Impl& grid = *impl_;
    grid.spheres = primitives.spheres;
    grid.triangles = primitives.triangles;
    const std::size_t n = grid.spheres.size() + grid.triangles.size();

    // 1. Each primitive's box, and the box of them all
    std::vector<Aabb> boxes;
    boxes.reserve(n);
    for (const Sphere& sphere : grid.spheres) boxes.push_back(bounds_of(sphere));
    for (const Triangle& triangle : grid.triangles) boxes.push_back(bounds_of(triangle));
    Aabb bounds;
    for (const Aabb& box : boxes) bounds.add(box);
    if (bounds.empty()) return;  // nothing to hold: every query misses

    // 2. The grid's box, grown by the margin, and its resolution
    const double margin = cell_margin(bounds);
    grid.box = Aabb{bounds.min - Vec3(margin), bounds.max + Vec3(margin)};
    grid.resolution = grid_resolution(bounds, n);
    grid.cell_size = grid.box.extent() / Vec3(grid.resolution);
    grid.cells_per_unit = Vec3(grid.resolution) / grid.box.extent();

    // 3. The cells each primitive's box (grown by the margin) overlaps: a range per axis
    struct Range {
        glm::ivec3 low;
        glm::ivec3 high;
    };
    std::vector<Range> ranges(n);
    for (std::size_t k = 0; k < n; ++k) {
        if (boxes[k].empty()) {
            ranges[k] = {glm::ivec3(0), glm::ivec3(-1)};  // goes nowhere
            continue;
        }
        for (int axis = 0; axis < 3; ++axis) {
            ranges[k].low[axis] = grid.cell_of(boxes[k].min[axis] - margin, axis);
            ranges[k].high[axis] = grid.cell_of(boxes[k].max[axis] + margin, axis);
        }
    }
    const auto for_each_cell = [&](const Range& range, auto&& action) {
        for (int z = range.low.z; z <= range.high.z; ++z) {
            for (int y = range.low.y; y <= range.high.y; ++y) {
                for (int x = range.low.x; x <= range.high.x; ++x) action(grid.index({x, y, z}));
            }
        }
    };

    // Count each cell's primitives, turn the counts into where each list begins, then fill
    const std::size_t cell_count =
        static_cast<std::size_t>(grid.resolution.x) * grid.resolution.y * grid.resolution.z;
    grid.first.assign(cell_count + 1, 0);
    for (const Range& range : ranges) for_each_cell(range, [&](std::size_t c) { ++grid.first[c + 1]; });
    for (std::size_t c = 0; c < cell_count; ++c) grid.first[c + 1] += grid.first[c];
    grid.ids.resize(grid.first.back());
    std::vector<std::size_t> fill(grid.first.begin(), grid.first.end() - 1);
    for (std::size_t k = 0; k < n; ++k) {
        for_each_cell(ranges[k], [&](std::size_t c) { grid.ids[fill[c]++] = static_cast<std::uint32_t>(k); });
    }
}

UniformGrid::~UniformGrid() = default;
UniformGrid::UniformGrid(UniformGrid&&) noexcept = default;
UniformGrid& UniformGrid::operator=(UniformGrid&&) noexcept = default;

std::optional<PrimitiveHit> UniformGrid::closest_hit(const Ray& ray, TraversalStats* stats) const {
    // Each primitive tested with t_max cut to the best t so far, the best kept by comes_before,
    // as in the BVH; the walk goes on while the next cell begins at or before the best t.
    Ray nearer = ray;
    std::optional<PrimitiveHit> best;
    walk(
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
    walk(
        *impl_, ray, stats, [&] { return ray.t_max; },
        [&](std::uint32_t id) { return found = test_primitive(*impl_, id, ray).has_value(); });
    return found;
}

glm::ivec3 UniformGrid::resolution() const {
    return impl_->resolution;
}

UniformGridData UniformGrid::cells() const {
    UniformGridData data;
    data.bounds = impl_->box;
    data.resolution = impl_->resolution;
    data.cells.resize(impl_->first.empty() ? 0 : impl_->first.size() - 1);
    for (std::size_t cell = 0; cell < data.cells.size(); ++cell)
        data.cells[cell].assign(impl_->ids.begin() + impl_->first[cell],
                                impl_->ids.begin() + impl_->first[cell + 1]);
    return data;
}

}  // namespace raystep
