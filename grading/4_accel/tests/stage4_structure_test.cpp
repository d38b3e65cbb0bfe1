// A stage-4 structure handed back as data (grading/4_accel/stage4_structure.h): the reference's
// structures pass as they are, each way of breaking one is named, and the grader's walks count the
// work a structure saves.

#include <string>
#include <vector>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "grading/4_accel/stage4_structure.h"

using namespace raystep;
using namespace raystep::grade;

namespace {

// n small triangles and n / 4 spheres strewn through [-1, 1]^3.
PrimitiveList strewn(int n) {
    PortableRandom random(4);
    PrimitiveList list;
    for (int k = 0; k < n; ++k) {
        const Vec3 c = random.point(1.0);
        list.triangles.push_back({c, c + random.point(0.05), c + random.point(0.05)});
    }
    for (int k = 0; k < n / 4; ++k)
        list.spheres.push_back({random.point(1.0), 0.02});
    return list;
}

std::vector<Ray> rays_through(int n) {
    PortableRandom random(5);
    std::vector<Ray> rays;
    for (int k = 0; k < n; ++k) {
        const Vec3 origin = 3.0 * random.unit_vector();
        rays.push_back({origin, random.point(0.8) - origin});
    }
    return rays;
}

std::size_t count_of(const PrimitiveList& list) {
    return list.spheres.size() + list.triangles.size();
}

// One leaf holding everything, in a box that holds it all.
std::vector<BvhNodeData> one_leaf(const PrimitiveList& list) {
    BvhNodeData leaf;
    leaf.box = {Vec3(-2.0), Vec3(2.0)};
    for (std::size_t id = 0; id < count_of(list); ++id)
        leaf.primitives.push_back(id);
    return {leaf};
}

double mean(const std::vector<std::uint64_t>& counts) {
    double sum = 0.0;
    for (const std::uint64_t c : counts)
        sum += double(c);
    return sum / double(counts.size());
}

bool names(const std::optional<std::string>& problem, const std::string& words) {
    return problem && problem->find(words) != std::string::npos;
}

}  // namespace

TEST_CASE("bvh_problem: the reference's trees and a single leaf of everything are BVHs",
          "[stage4]") {
    const PrimitiveList list = strewn(400);
    CHECK_FALSE(bvh_problem(Bvh(list, BvhSplit::sah).nodes(), list));
    CHECK_FALSE(bvh_problem(Bvh(list, BvhSplit::median).nodes(), list));
    CHECK_FALSE(bvh_problem(one_leaf(list), list));
    CHECK_FALSE(bvh_problem({}, PrimitiveList{}));
}

TEST_CASE("bvh_problem: each way a tree can be wrong is named", "[stage4]") {
    const PrimitiveList list = strewn(400);
    const std::vector<BvhNodeData> tree = Bvh(list, BvhSplit::sah).nodes();
    REQUIRE(tree.size() > 3);
    REQUIRE_FALSE(tree[0].children.empty());

    CHECK(names(bvh_problem({}, list), "empty"));

    std::vector<BvhNodeData> shrunk = tree;  // the root's box misses most of the scene
    shrunk[0].box = {Vec3(-0.1), Vec3(0.1)};
    CHECK(names(bvh_problem(shrunk, list), "does not hold"));

    std::vector<BvhNodeData> shared = tree;  // a child listed twice: two parents
    shared[0].children.push_back(shared[0].children[0]);
    CHECK(names(bvh_problem(shared, list), "exactly one parent"));

    std::vector<BvhNodeData> beyond = tree;
    beyond[0].children.push_back(tree.size());
    CHECK(names(bvh_problem(beyond, list), "is not a node"));

    std::vector<BvhNodeData> cycle = tree;  // two nodes that are each other's child
    cycle.push_back({tree[0].box, {tree.size() + 1}, {}});
    cycle.push_back({tree[0].box, {tree.size()}, {}});
    CHECK(names(bvh_problem(cycle, list), "cycle"));

    std::vector<BvhNodeData> lost = one_leaf(list);  // the last triangle in no leaf
    lost[0].primitives.pop_back();
    CHECK(names(bvh_problem(lost, list), "is in no leaf"));

    std::vector<BvhNodeData> stranger = one_leaf(list);
    stranger[0].primitives.push_back(count_of(list));
    CHECK(names(bvh_problem(stranger, list), "beyond the"));

    std::vector<BvhNodeData> nan_box = one_leaf(list);
    nan_box[0].box.min.x = std::nan("");
    CHECK(names(bvh_problem(nan_box, list), "does not hold"));
}

TEST_CASE("grid_problem: the reference's grid passes, and a cell that lacks a primitive is named",
          "[stage4]") {
    const PrimitiveList list = strewn(400);
    const UniformGridData grid = UniformGrid(list).cells();
    CHECK_FALSE(grid_problem(grid, list));

    UniformGridData lacking = grid;  // the first listed primitive left out of its first cell
    for (std::vector<std::size_t>& cell : lacking.cells) {
        if (cell.empty()) continue;
        cell.erase(cell.begin());
        break;
    }
    CHECK(names(grid_problem(lacking, list), "is not listed in cell"));

    UniformGridData too_few = grid;
    too_few.cells.pop_back();
    CHECK(names(grid_problem(too_few, list), "cell lists for"));

    UniformGridData small = grid;
    small.bounds = {Vec3(-0.5), Vec3(0.5)};
    CHECK(names(grid_problem(small, list), "is not inside the grid's box"));

    UniformGridData no_cells = grid;
    no_cells.resolution.y = 0;
    CHECK(names(grid_problem(no_cells, list), "at least one"));
}

TEST_CASE("grid_problem: a flat triangle on a plane between cells may be listed on either side",
          "[stage4]") {
    PrimitiveList list;
    list.triangles.push_back({{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.1, 0.9, 0.5}});
    UniformGridData grid;
    grid.bounds = {Vec3(0.0), Vec3(1.0)};
    grid.resolution = {1, 1, 2};  // the plane z = 0.5 lies between the two cells
    grid.cells = {{0}, {}};
    CHECK_FALSE(grid_problem(grid, list));
    grid.cells = {{}, {0}};
    CHECK_FALSE(grid_problem(grid, list));
    grid.cells = {{}, {}};
    CHECK(names(grid_problem(grid, list), "is not listed in cell"));
}

TEST_CASE("walk_bvh: a single leaf costs a test per primitive; the reference's tree far fewer",
          "[stage4]") {
    const PrimitiveList list = strewn(800);
    const std::vector<Ray> rays = rays_through(100);
    const WalkCost leaf = walk_bvh(one_leaf(list), list, rays);
    CHECK(mean(leaf.tests) == double(count_of(list)));
    CHECK(mean(leaf.nodes) == 1.0);
    const WalkCost tree = walk_bvh(Bvh(list, BvhSplit::sah).nodes(), list, rays);
    CHECK(mean(tree.tests) < 0.1 * double(count_of(list)));
    CHECK(mean(tree.nodes) > 1.0);
}

TEST_CASE("walk_grid: one cell costs a test per primitive; the reference's grid far fewer",
          "[stage4]") {
    const PrimitiveList list = strewn(800);
    const std::vector<Ray> rays = rays_through(100);
    UniformGridData one_cell;
    one_cell.bounds = {Vec3(-2.0), Vec3(2.0)};
    one_cell.resolution = {1, 1, 1};
    one_cell.cells = {one_leaf(list)[0].primitives};
    REQUIRE_FALSE(grid_problem(one_cell, list));
    const WalkCost whole = walk_grid(one_cell, list, rays);
    CHECK(mean(whole.tests) == double(count_of(list)));
    const WalkCost grid = walk_grid(UniformGrid(list).cells(), list, rays);
    CHECK(mean(grid.tests) < 0.1 * double(count_of(list)));
    CHECK(mean(grid.nodes) > 1.0);

    // A ray that passes beside the grid's box visits no cell
    const WalkCost beside = walk_grid(one_cell, list, {{{5.0, 5.0, 5.0}, {1.0, 0.0, 0.0}}});
    CHECK(beside.nodes[0] == 0);
    CHECK(beside.tests[0] == 0);
}
