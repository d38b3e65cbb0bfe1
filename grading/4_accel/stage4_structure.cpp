#include "grading/4_accel/stage4_structure.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

namespace raystep::grade {

namespace {

// How far a box may fall short of what it must hold, as a share of the scene's size: a millionth,
// far beyond the rounding of boxes kept in double or in float (2^-24 of a coordinate), far below
// any box that is wrong. The walks below only count work, so a box short by this much changes a
// count by a test now and then, never a verdict.
constexpr double kBoxSlack = 1e-6;

std::size_t primitive_count(const PrimitiveList& primitives) {
    return primitives.spheres.size() + primitives.triangles.size();
}

// The box of primitive `id`, numbered as closest_hit numbers them: the sphere's centre -+ radius,
// with no padding (a student's box may have none), or the triangle's three vertices.
Aabb primitive_box(const PrimitiveList& primitives, std::size_t id) {
    const std::size_t spheres = primitives.spheres.size();
    if (id >= spheres) return bounds_of(primitives.triangles[id - spheres]);
    const Sphere& sphere = primitives.spheres[id];
    return {sphere.center - Vec3(sphere.radius), sphere.center + Vec3(sphere.radius)};
}

std::string primitive_name(const PrimitiveList& primitives, std::size_t id) {
    const std::size_t spheres = primitives.spheres.size();
    return id < spheres ? "sphere " + std::to_string(id)
                        : "triangle " + std::to_string(id - spheres);
}

// The slack in scene units: kBoxSlack of the largest coordinate any primitive's box reaches.
double scene_slack(const PrimitiveList& primitives) {
    double size = 0.0;
    for (std::size_t id = 0; id < primitive_count(primitives); ++id) {
        const Aabb box = primitive_box(primitives, id);
        if (box.empty()) continue;
        for (int axis = 0; axis < 3; ++axis)
            size = std::max({size, std::abs(box.min[axis]), std::abs(box.max[axis])});
    }
    return kBoxSlack * std::max(size, 1e-300);
}

// True when `outer` holds `inner` to within `slack`; false for a NaN anywhere (each comparison
// is written so that NaN fails it).
bool holds(const Aabb& outer, const Aabb& inner, double slack) {
    if (inner.empty() && !std::isnan(inner.min.x + inner.max.x)) return true;
    for (int axis = 0; axis < 3; ++axis) {
        if (!(outer.min[axis] <= inner.min[axis] + slack)) return false;
        if (!(outer.max[axis] >= inner.max[axis] - slack)) return false;
    }
    return true;
}

std::string box_text(const Aabb& box) {
    char text[200];
    std::snprintf(text, sizeof text, "(%.17g, %.17g, %.17g) to (%.17g, %.17g, %.17g)", box.min.x,
                  box.min.y, box.min.z, box.max.x, box.max.y, box.max.z);
    return text;
}

// The reference's primitive test of `id` against `ray`.
std::optional<Hit> test_primitive(const PrimitiveList& primitives, std::size_t id, const Ray& ray) {
    const std::size_t spheres = primitives.spheres.size();
    return id < spheres ? intersect_sphere(ray, primitives.spheres[id])
                        : intersect_triangle(ray, primitives.triangles[id - spheres]);
}

Vec3 inverse_of(const Vec3& direction) {
    return Vec3(1.0 / direction.x, 1.0 / direction.y, 1.0 / direction.z);
}

// Tests primitive `id` once per ray (`stamp` is the ray's number, `tested` each primitive's last),
// and cuts `nearer.t_max` to a nearer hit.
void test_once(const PrimitiveList& primitives, std::size_t id, std::uint64_t stamp,
               std::vector<std::uint64_t>& tested, Ray& nearer, std::uint64_t& tests) {
    if (tested[id] == stamp) return;
    tested[id] = stamp;
    ++tests;
    const std::optional<Hit> hit = test_primitive(primitives, id, nearer);
    if (hit && hit->t < nearer.t_max) nearer.t_max = hit->t;
}

}  // namespace

std::optional<std::string> bvh_problem(const std::vector<BvhNodeData>& nodes,
                                       const PrimitiveList& primitives) {
    const std::size_t count = primitive_count(primitives);
    if (nodes.empty()) {
        if (count == 0) return std::nullopt;
        return "nodes() is empty, for a tree over " + std::to_string(count) + " primitives";
    }
    const double slack = scene_slack(primitives);

    // Indices in range, and each node a leaf or an inner node
    std::vector<int> parents(nodes.size(), 0);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const BvhNodeData& node = nodes[k];
        if (!node.children.empty() && !node.primitives.empty()) {
            return "node " + std::to_string(k) + " has both children and primitives";
        }
        for (const std::size_t child : node.children) {
            if (child >= nodes.size()) {
                return "node " + std::to_string(k) + "'s child " + std::to_string(child) +
                       " is not a node (there are " + std::to_string(nodes.size()) + ")";
            }
            ++parents[child];
        }
        for (const std::size_t id : node.primitives) {
            if (id >= count) {
                return "node " + std::to_string(k) + " lists primitive " + std::to_string(id) +
                       ", beyond the " + std::to_string(count) + " there are";
            }
        }
    }

    // A tree from node 0: the root no one's child, every other node exactly one's, all reached
    if (parents[0] != 0) return std::string("node 0, the root, is the child of another node");
    for (std::size_t k = 1; k < nodes.size(); ++k) {
        if (parents[k] != 1) {
            return "node " + std::to_string(k) + " is the child of " + std::to_string(parents[k]) +
                   " nodes, where a tree's node has exactly one parent";
        }
    }
    std::size_t reached = 0;
    std::vector<bool> in_leaf(count, false);
    std::deque<std::size_t> pending{0};
    while (!pending.empty() && reached <= nodes.size()) {
        const BvhNodeData& node = nodes[pending.front()];
        pending.pop_front();
        ++reached;
        pending.insert(pending.end(), node.children.begin(), node.children.end());
        for (const std::size_t id : node.primitives)
            in_leaf[id] = true;
    }
    if (reached != nodes.size()) {
        return std::to_string(nodes.size() - std::min(reached, nodes.size())) +
               " nodes cannot be reached from the root: they form a cycle of their own";
    }
    for (std::size_t id = 0; id < count; ++id) {
        if (!in_leaf[id]) return primitive_name(primitives, id) + " is in no leaf";
    }

    // Every box holds what is below it
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const BvhNodeData& node = nodes[k];
        for (const std::size_t child : node.children) {
            if (!holds(node.box, nodes[child].box, slack)) {
                return "node " + std::to_string(k) + "'s box " + box_text(node.box) +
                       " does not hold its child " + std::to_string(child) + "'s box " +
                       box_text(nodes[child].box);
            }
        }
        for (const std::size_t id : node.primitives) {
            const Aabb box = primitive_box(primitives, id);
            if (!holds(node.box, box, slack)) {
                return "leaf " + std::to_string(k) + "'s box " + box_text(node.box) +
                       " does not hold " + primitive_name(primitives, id) + ", whose box is " +
                       box_text(box);
            }
        }
    }
    return std::nullopt;
}

std::optional<std::string> grid_problem(const UniformGridData& grid,
                                        const PrimitiveList& primitives) {
    const std::size_t count = primitive_count(primitives);
    const double slack = scene_slack(primitives);

    // Its shape: cells along each axis, a list for each cell, a finite box
    std::size_t cells = 1;
    for (int axis = 0; axis < 3; ++axis) {
        if (grid.resolution[axis] < 1) {
            return "the resolution has " + std::to_string(grid.resolution[axis]) +
                   " cells along an axis, where a grid has at least one";
        }
        cells *= static_cast<std::size_t>(grid.resolution[axis]);
        if (!std::isfinite(grid.bounds.min[axis]) || !std::isfinite(grid.bounds.max[axis]) ||
            !(grid.bounds.min[axis] <= grid.bounds.max[axis])) {
            return "the grid's box " + box_text(grid.bounds) + " is not a finite box";
        }
    }
    if (grid.cells.size() != cells) {
        return "the grid has " + std::to_string(grid.cells.size()) + " cell lists for " +
               std::to_string(cells) + " cells";
    }
    std::vector<std::vector<std::size_t>> sorted = grid.cells;
    for (std::vector<std::size_t>& list : sorted) {
        std::sort(list.begin(), list.end());
        if (!list.empty() && list.back() >= count) {
            return "a cell lists primitive " + std::to_string(list.back()) + ", beyond the " +
                   std::to_string(count) + " there are";
        }
    }

    // Every primitive in every cell its box overlaps: along each axis, the cells whose inside,
    // shrunk by the slack, meets the box; where none does (a box on a plane between cells), one of
    // the two cells on either side
    for (std::size_t id = 0; id < count; ++id) {
        const Aabb box = primitive_box(primitives, id);
        if (box.empty()) continue;
        if (!holds(grid.bounds, box, slack)) {
            return primitive_name(primitives, id) + ", whose box is " + box_text(box) +
                   ", is not inside the grid's box " + box_text(grid.bounds);
        }
        int low[3];
        int high[3];
        bool either_side[3];
        for (int axis = 0; axis < 3; ++axis) {
            const int last = grid.resolution[axis] - 1;
            const double size = grid.bounds.extent()[axis] / grid.resolution[axis];
            either_side[axis] = false;
            if (!(size > 0.0)) {
                low[axis] = 0;
                high[axis] = last;
                continue;
            }
            const double from = (box.min[axis] - grid.bounds.min[axis] + slack) / size - 1.0;
            const double to = (box.max[axis] - grid.bounds.min[axis] - slack) / size;
            low[axis] = static_cast<int>(std::clamp(std::ceil(from), 0.0, double(last)));
            high[axis] = static_cast<int>(std::clamp(std::floor(to), 0.0, double(last)));
            if (low[axis] > high[axis]) {
                std::swap(low[axis], high[axis]);
                either_side[axis] = true;
            }
        }
        const auto index = [&](int x, int y, int z) {
            return (static_cast<std::size_t>(z) * grid.resolution.y + y) * grid.resolution.x + x;
        };
        const auto lists = [&](std::size_t cell) {
            return std::binary_search(sorted[cell].begin(), sorted[cell].end(), id);
        };
        // A cell of the box's range, with the either-side axes free: listed in one of those
        for (int z = low[2]; z <= high[2]; ++z) {
            for (int y = low[1]; y <= high[1]; ++y) {
                for (int x = low[0]; x <= high[0]; ++x) {
                    const int cell[3] = {x, y, z};
                    bool free_axis_first = false;
                    for (int axis = 0; axis < 3; ++axis)
                        free_axis_first |= either_side[axis] && cell[axis] != low[axis];
                    if (free_axis_first) continue;  // checked with the first of its pair
                    bool listed = false;
                    for (int choice = 0; choice < 8 && !listed; ++choice) {
                        int at[3];
                        bool valid = true;
                        for (int axis = 0; axis < 3; ++axis) {
                            const bool other = (choice >> axis) & 1;
                            if (other && !either_side[axis]) valid = false;
                            at[axis] = other ? high[axis] : cell[axis];
                        }
                        listed = valid && lists(index(at[0], at[1], at[2]));
                    }
                    if (!listed) {
                        return primitive_name(primitives, id) + ", whose box is " + box_text(box) +
                               ", is not listed in cell (" + std::to_string(x) + ", " +
                               std::to_string(y) + ", " + std::to_string(z) +
                               "), which it overlaps";
                    }
                }
            }
        }
    }
    return std::nullopt;
}

WalkCost walk_bvh(const std::vector<BvhNodeData>& nodes, const PrimitiveList& primitives,
                  const std::vector<Ray>& rays) {
    WalkCost cost;
    std::vector<std::uint64_t> tested(primitive_count(primitives), 0);
    struct Pending {
        std::size_t node;
        double enter;
    };
    std::vector<Pending> stack;
    for (std::size_t r = 0; r < rays.size(); ++r) {
        std::uint64_t visited = 0;
        std::uint64_t tests = 0;
        Ray nearer = rays[r];
        const Vec3 inverse = inverse_of(nearer.direction);
        stack.clear();
        if (!nodes.empty()) {
            if (const std::optional<Interval> root =
                    intersect_aabb(nearer, inverse, nodes[0].box)) {
                stack.push_back({0, root->enter});
            }
        }
        while (!stack.empty()) {
            const Pending next = stack.back();
            stack.pop_back();
            // A node that starts beyond the best hit holds nothing nearer
            if (next.enter > nearer.t_max) continue;
            ++visited;
            const BvhNodeData& node = nodes[next.node];
            for (const std::size_t id : node.primitives)
                test_once(primitives, id, r + 1, tested, nearer, tests);
            // The children the ray enters, the nearest pushed last, so popped first
            const std::size_t first = stack.size();
            for (const std::size_t child : node.children) {
                if (const std::optional<Interval> entered =
                        intersect_aabb(nearer, inverse, nodes[child].box)) {
                    stack.push_back({child, entered->enter});
                }
            }
            std::sort(stack.begin() + static_cast<std::ptrdiff_t>(first), stack.end(),
                      [](const Pending& a, const Pending& b) { return a.enter > b.enter; });
        }
        cost.nodes.push_back(visited);
        cost.tests.push_back(tests);
    }
    return cost;
}

WalkCost walk_grid(const UniformGridData& grid, const PrimitiveList& primitives,
                   const std::vector<Ray>& rays) {
    WalkCost cost;
    std::vector<std::uint64_t> tested(primitive_count(primitives), 0);
    const Vec3 size = grid.bounds.extent() / Vec3(grid.resolution);
    for (std::size_t r = 0; r < rays.size(); ++r) {
        std::uint64_t visited = 0;
        std::uint64_t tests = 0;
        Ray nearer = rays[r];
        const Vec3 inverse = inverse_of(nearer.direction);
        const std::optional<Interval> inside = intersect_aabb(nearer, inverse, grid.bounds);
        if (inside) {
            // The cell where the ray enters, and per axis the step, the t of the next plane
            // between cells, and the t from one plane to the next
            int cell[3];
            int step[3];
            double next_plane[3];
            double delta[3];
            const Vec3 entry = nearer.origin + inside->enter * nearer.direction;
            for (int axis = 0; axis < 3; ++axis) {
                const double d = nearer.direction[axis];
                const bool walks = size[axis] > 0.0 && d != 0.0;
                const double at =
                    walks ? std::floor((entry[axis] - grid.bounds.min[axis]) / size[axis]) : 0.0;
                cell[axis] =
                    static_cast<int>(std::clamp(at, 0.0, double(grid.resolution[axis] - 1)));
                step[axis] = walks ? (d > 0.0 ? 1 : -1) : 0;
                const double plane =
                    grid.bounds.min[axis] + (cell[axis] + (step[axis] > 0 ? 1 : 0)) * size[axis];
                next_plane[axis] = walks ? (plane - nearer.origin[axis]) * inverse[axis] : HUGE_VAL;
                delta[axis] = walks ? size[axis] * std::abs(inverse[axis]) : HUGE_VAL;
            }
            for (;;) {
                ++visited;
                const std::size_t index =
                    (static_cast<std::size_t>(cell[2]) * grid.resolution.y + cell[1]) *
                        grid.resolution.x +
                    cell[0];
                for (const std::size_t id : grid.cells[index])
                    test_once(primitives, id, r + 1, tested, nearer, tests);
                // On to the nearest plane, while the next cell begins at or before the best hit
                const int axis = next_plane[0] < next_plane[1]
                                     ? (next_plane[0] < next_plane[2] ? 0 : 2)
                                     : (next_plane[1] < next_plane[2] ? 1 : 2);
                if (!(next_plane[axis] <= nearer.t_max) || !(next_plane[axis] <= inside->exit)) {
                    break;
                }
                cell[axis] += step[axis];
                if (cell[axis] < 0 || cell[axis] >= grid.resolution[axis]) break;
                next_plane[axis] += delta[axis];
            }
        }
        cost.nodes.push_back(visited);
        cost.tests.push_back(tests);
    }
    return cost;
}

}  // namespace raystep::grade
