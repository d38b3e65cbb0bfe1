// Public tests for stage 4, the uniform grid. Run them with `ctest --preset student -L stage4`,
// one method's with `build/student/bin/raystep_stage4_tests "UniformGrid::occluded:*"`. Every
// UniformGrid test builds a grid first, so the constructor comes before the rest.
//
// Each test calls your code before its CHECKs: a stub ends the test case at its first call and
// is reported once. A failure prints the ray; where a test tries many rays, it stops at the first
// that fails.
//
// A grid must give exactly closest_hit's answer: the same primitive and the same t, compared
// with ==. Both call the same stage-3 tests; only the order differs.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "base/testing/number_text.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/3_intersect/tests/hit_text.h"
#include "stages/4_accel/uniform_grid.h"

using namespace raystep;
using raystep::testing::text;
using raystep::testing::uses;

namespace {

// n small random triangles, n / 4 spheres and a few large triangles across the whole scene, all in
// [-5, 5]^3. The large ones lie in many cells: a ray meets them in one cell and hits them in
// another.
PrimitiveList random_scene(PortableRandom& random, int n) {
    PrimitiveList list;
    for (int k = 0; k < n; ++k) {
        const Vec3 c = random.point(4.0);
        const double s = random.uniform(0.05, 1.0);
        list.triangles.push_back(
            {c + s * random.point(1.0), c + s * random.point(1.0), c + s * random.point(1.0)});
    }
    for (int k = 0; k < 5; ++k) {
        list.triangles.push_back({random.point(5.0), random.point(5.0), random.point(5.0)});
    }
    for (int k = 0; k < n / 4; ++k)
        list.spheres.push_back({random.point(4.0), 0.5 * random.uniform(0.05, 1.0)});
    return list;
}

// From outside the scene, aimed at a point in it.
Ray ray_from_outside(PortableRandom& random) {
    const Vec3 origin = random.point(9.0);
    return {origin, random.point(5.0) - origin};
}

// From inside the scene, in any direction.
Ray ray_from_inside(PortableRandom& random) {
    return {random.point(4.5), random.point(1.0)};
}

// The grid's answer is closest_hit's, bit for bit; a difference ends the test case.
void check_same(const Ray& ray, const std::optional<PrimitiveHit>& got,
                const std::optional<PrimitiveHit>& expected) {
    INFO(text(ray));
    INFO("The grid finds " << text(got) << ", closest_hit " << text(expected));
    REQUIRE(got.has_value() == expected.has_value());
    if (!got) return;
    REQUIRE(got->kind == expected->kind);
    REQUIRE(got->index == expected->index);
    REQUIRE(got->hit.t == expected->hit.t);
}

// Two walls of 5 x 5 spheres of radius 0.3, in the planes x = 0 and x = 10, with empty cells
// between them.
PrimitiveList two_walls_of_spheres() {
    PrimitiveList walls;
    for (int k = 0; k < 25; ++k) {
        walls.spheres.push_back({{0, k % 5, k / 5}, 0.3});
        walls.spheres.push_back({{10, k % 5, k / 5}, 0.3});
    }
    return walls;
}

int primitive_count(const PrimitiveList& list) {
    return static_cast<int>(list.spheres.size() + list.triangles.size());
}

}  // namespace

TEST_CASE("UniformGrid::resolution: grid_resolution of the primitives' bounds", "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    PortableRandom random(1);
    const PrimitiveList list = random_scene(random, 400);
    Aabb bounds;
    for (const Sphere& s : list.spheres)
        bounds.add(bounds_of(s));
    for (const Triangle& t : list.triangles)
        bounds.add(bounds_of(t));
    const glm::ivec3 expected =
        grid_resolution(bounds, list.spheres.size() + list.triangles.size());
    CHECK(UniformGrid(list).resolution() == expected);
    CHECK(UniformGrid(PrimitiveList{}).resolution() == glm::ivec3(1, 1, 1));
}

TEST_CASE("UniformGrid::cells: every primitive is listed in every cell its box overlaps",
          "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    PortableRandom random(12);
    const PrimitiveList list = random_scene(random, 300);
    const UniformGrid grid(list);
    const UniformGridData data = grid.cells();
    REQUIRE(data.resolution == grid.resolution());
    const glm::ivec3 n = data.resolution;
    REQUIRE(data.cells.size() == static_cast<std::size_t>(n.x) * n.y * n.z);
    const Vec3 size = data.bounds.extent() / Vec3(n);
    const auto listed = [&](int x, int y, int z, std::size_t id) {
        const std::vector<std::size_t>& cell =
            data.cells[(static_cast<std::size_t>(z) * n.y + y) * n.x + x];
        return std::find(cell.begin(), cell.end(), id) != cell.end();
    };
    const std::size_t count = list.spheres.size() + list.triangles.size();
    for (std::size_t id = 0; id < count; ++id) {
        CAPTURE(id);
        const Aabb box = id < list.spheres.size()
                             ? bounds_of(list.spheres[id])
                             : bounds_of(list.triangles[id - list.spheres.size()]);
        // The cells from the one holding the box's min corner to the one holding its max corner
        glm::ivec3 low;
        glm::ivec3 high;
        for (int axis = 0; axis < 3; ++axis) {
            const auto cell = [&](double x) {
                return std::clamp(
                    static_cast<int>(std::floor((x - data.bounds.min[axis]) / size[axis])), 0,
                    n[axis] - 1);
            };
            low[axis] = cell(box.min[axis]);
            high[axis] = cell(box.max[axis]);
        }
        for (int z = low.z; z <= high.z; ++z) {
            for (int y = low.y; y <= high.y; ++y) {
                for (int x = low.x; x <= high.x; ++x) {
                    CAPTURE(x, y, z);
                    REQUIRE(listed(x, y, z, id));
                }
            }
        }
    }
}

TEST_CASE("UniformGrid::closest_hit: equals closest_hit on random scenes, from outside and inside",
          "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    for (const int seed : {1, 2, 3}) {
        PortableRandom random(static_cast<std::uint64_t>(seed));
        const PrimitiveList list = random_scene(random, 400);
        const UniformGrid grid(list);
        for (int k = 0; k < 1000; ++k) {
            const Ray ray = k % 2 == 0 ? ray_from_outside(random) : ray_from_inside(random);
            CAPTURE(seed, k);
            check_same(ray, grid.closest_hit(ray), closest_hit(ray, list));
        }
    }
}

TEST_CASE("UniformGrid::closest_hit: equals closest_hit on tiny, huge and far-off scenes",
          "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    INFO(
        "The same scenes scaled by 1e-3 and 1e3 and moved 1e5 away: cell sizes, crossings and "
        "rounding all scale with them, and nothing may be tuned to scenes of size 10 at the "
        "origin.");
    for (const double scale : {1e-3, 1e3}) {
        for (const double offset : {0.0, 1e5}) {
            PortableRandom random(10);
            PrimitiveList list = random_scene(random, 300);
            const Vec3 shift(offset, -offset, 0.5 * offset);
            for (Sphere& s : list.spheres)
                s = {shift + scale * s.center, scale * s.radius};
            for (Triangle& t : list.triangles) {
                t = {shift + scale * t.p0, shift + scale * t.p1, shift + scale * t.p2};
            }
            const UniformGrid grid(list);
            for (int k = 0; k < 500; ++k) {
                Ray ray = k % 2 == 0 ? ray_from_outside(random) : ray_from_inside(random);
                ray.origin = shift + scale * ray.origin;
                CAPTURE(scale, offset, k);
                check_same(ray, grid.closest_hit(ray), closest_hit(ray, list));
            }
        }
    }
}

TEST_CASE("UniformGrid::closest_hit: axis-parallel rays and short rays", "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    PortableRandom random(4);
    const PrimitiveList list = random_scene(random, 300);
    const UniformGrid grid(list);
    for (int k = 0; k < 600; ++k) {
        CAPTURE(k);
        const Vec3 origin = random.point(6.0);
        Vec3 axis(0.0);
        axis[k % 3] = k % 2 == 0 ? 1.0 : -1.0;
        const Ray axis_ray{origin, axis};
        check_same(axis_ray, grid.closest_hit(axis_ray), closest_hit(axis_ray, list));
        const Ray short_ray{origin, random.point(1.0), 0.0, 2.0};
        check_same(short_ray, grid.closest_hit(short_ray), closest_hit(short_ray, list));
        const Ray late_ray{origin, random.point(1.0), 3.0};  // t_min past the origin
        check_same(late_ray, grid.closest_hit(late_ray), closest_hit(late_ray, list));
    }
}

TEST_CASE("UniformGrid::closest_hit: rays that start on, run along or hit the planes between cells",
          "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    INFO(
        "20 triangles in [0, 4]^3, so 4 x 4 x 4 cells whose planes are at (or, with the grid's "
        "small growth of its box, a hair from) x, y, z = 0, 1, 2, 3, 4. On each plane x, y or z = "
        "1, 2, 3: the square [1, 3]^2 of the other two coordinates, as two triangles, whose edges "
        "lie on planes between cells. Two small triangles at the corners stretch the bounds to [0, "
        "4]^3.");
    PrimitiveList list;
    for (int axis = 0; axis < 3; ++axis) {
        for (int plane = 1; plane <= 3; ++plane) {
            const auto at = [&](double u, double v) {
                Vec3 p;
                p[axis] = plane;
                p[(axis + 1) % 3] = u;
                p[(axis + 2) % 3] = v;
                return p;
            };
            list.triangles.push_back({at(1, 1), at(3, 1), at(1, 3)});
            list.triangles.push_back({at(3, 3), at(1, 3), at(3, 1)});
        }
    }
    list.triangles.push_back({{0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}});
    list.triangles.push_back({{4, 4, 4}, {3.5, 4, 4}, {4, 3.5, 4}});
    const UniformGrid grid(list);
    REQUIRE(grid.resolution() == glm::ivec3(4, 4, 4));

    // Origins on the planes (and off the grid, at -1 and 5), each coordinate nudged by -1, 0 or
    // +1 ulp so that some land exactly on the grid's own planes, whatever its growth; directions
    // along the axes (running inside a plane), along diagonals, and general ones.
    const double values[] = {-1, 0, 1, 1.5, 2, 2.5, 3, 4, 5};
    const Vec3 directions[] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},       {0, -1, 0},
                               {0, 0, 1},  {0, 0, -1}, {1, 1, 0},       {0, -1, 1},
                               {1, 0, -1}, {1, 1, 1},  {-1, 0.5, 0.25}, {0.3, -1, 0.7}};
    PortableRandom random(5);
    const auto nudged = [&](double x) {
        const int n = static_cast<int>(random.integer(-1, 1));
        return n == 0 ? x : std::nextafter(x, n * std::numeric_limits<double>::infinity());
    };
    int hits = 0;
    for (const double x : values) {
        for (const double y : values) {
            for (const double z : values) {
                for (const Vec3& direction : directions) {
                    const Ray ray{{nudged(x), nudged(y), nudged(z)}, direction};
                    CAPTURE(ray.origin.x, ray.origin.y, ray.origin.z);
                    CAPTURE(direction.x, direction.y, direction.z);
                    const std::optional<PrimitiveHit> expected = closest_hit(ray, list);
                    hits += expected.has_value();
                    check_same(ray, grid.closest_hit(ray), expected);
                }
            }
        }
    }
    CHECK(hits > 1200);  // the loop compared hits, not only misses
}

TEST_CASE("UniformGrid::closest_hit: ties go to the primitive closest_hit picks", "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    INFO(
        "closest_hit keeps, of hits at the same t, the primitive listed first (spheres, then "
        "triangles, each in list order); the grid meets them in another order. Small spheres at "
        "the edges give the grid its cells.");
    PrimitiveList list;
    for (const double z : {-3.0, -1.0, 1.0, 3.0}) {  // with the triangles: 4 x 4 x 4 cells
        for (const double x : {-3.0, 3.0}) {
            for (const double y : {-3.0, 3.0})
                list.spheres.push_back({{x, y, z}, 0.1});
        }
    }
    const Triangle t{{-2, -2, 0}, {2, -2, 0}, {0, 2, 0}};
    list.triangles = {t, t, t};
    const Ray down{{0, 0, 5}, {0, 0, -1}};
    {
        INFO("three copies: the first");
        const UniformGrid grid(list);
        REQUIRE(grid.resolution() == glm::ivec3(4, 4, 4));
        for (int k = 0; k < 25; ++k) {
            // Points well inside the triangle (at height y it spans |x| <= (2 - y) / 2), from
            // its bottom edge to near its top vertex, through several cells
            const double y = -1.8 + 0.6 * (k / 5);
            const double x = (2 - y) / 2 * (-0.8 + 0.4 * (k % 5));
            const Ray ray{{x, y, 5}, {0.01 * (k % 3), 0.01, -1}};
            CAPTURE(k);
            const std::optional<PrimitiveHit> hit = grid.closest_hit(ray);
            check_same(ray, hit, closest_hit(ray, list));
            REQUIRE(hit);
            REQUIRE(hit->index == 0);
        }
    }
    {
        INFO("a sphere touching at the same t: the sphere");
        // The sphere's t is exactly 5 when intersect_sphere rounds well (the reference's does);
        // whatever it is, the grid must pick what closest_hit picks.
        list.spheres.push_back({{0, 0, -1}, 1.0});
        const UniformGrid grid(list);
        check_same(down, grid.closest_hit(down), closest_hit(down, list));
    }
}

TEST_CASE(
    "UniformGrid::closest_hit: a tie met in a later cell still goes to the primitive listed first",
    "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    INFO(
        "Triangle 1, large, and triangle 0, small, both in z = 0; spheres at the corners give the "
        "grid 5 x 5 x 1 cells, 2.44 wide. The ray comes down at a slant into cell x = 2, which "
        "holds triangle 1 but not triangle 0, and hits both at x = 2, in cell x = 3. The grid "
        "meets triangle 1 first; with the reference's triangle test both hits are at t = 4 exactly "
        "(from this ray, every triangle in z = 0 gives t = 4), and closest_hit keeps triangle 0.");
    PrimitiveList list;
    for (const double z : {-1.5, 1.5}) {
        for (const double x : {-6.0, 6.0}) {
            for (const double y : {-6.0, 6.0})
                list.spheres.push_back({{x, y, z}, 0.1});
        }
    }
    list.triangles = {{{1.9, -0.1, 0}, {2.1, -0.1, 0}, {2, 0.1, 0}},
                      {{-2, -2, 0}, {4, -2, 0}, {1, 4, 0}}};
    const UniformGrid grid(list);
    REQUIRE(grid.resolution() == glm::ivec3(5, 5, 1));
    const Ray slant{{-1, 0, 4}, {0.75, 0, -1}};
    check_same(slant, grid.closest_hit(slant), closest_hit(slant, list));
}

TEST_CASE(
    "UniformGrid::closest_hit: a large triangle across many cells is tested once per ray "
    "(mailboxing)",
    "[stage4]") {
    INFO(
        "The triangle covers the bottom of the grid, z = 0, so it is in every cell of the bottom "
        "layer; small spheres in the top corner give the grid 4 x 4 x 4 cells.");
    PrimitiveList list;
    list.triangles.push_back({{0, 0, 0}, {10, 0, 0}, {0, 10, 0}});
    for (int k = 0; k < 27; ++k) {
        list.spheres.push_back(
            {{9 + 0.4 * (k % 3), 9 + 0.4 * (k / 3 % 3), 9 + 0.4 * (k / 9)}, 0.1});
    }
    const UniformGrid grid(list);
    {
        INFO("a ray above it, parallel, through the whole bottom layer");
        const Ray ray{{-1, 1, 0.5}, {1, 0, 0}};
        TraversalStats stats;
        CHECK_FALSE(grid.closest_hit(ray, &stats));
        CHECK(stats.nodes >= 3);
        CHECK(stats.primitive_tests == 1);
    }
    {
        INFO("a ray that meets it in the first cell and hits it in the last");
        // Into the bottom layer at x = 0, down to z = 0 at x = 9: the hit is 3 cells on.
        const Ray ray{{-1, 1, 0.5}, {1, 0, -0.05}};
        TraversalStats stats;
        const std::optional<PrimitiveHit> hit = grid.closest_hit(ray, &stats);
        check_same(ray, hit, closest_hit(ray, list));
        REQUIRE(hit);
        CHECK(stats.nodes >= 3);
        CHECK(stats.primitive_tests == 1);
    }
    {
        INFO("random rays: no primitive is tested twice");
        PortableRandom random(6);
        for (int k = 0; k < 500; ++k) {
            const Vec3 origin = Vec3(5.0) + random.point(8.0);
            const Ray ray{origin, Vec3(5.0) + random.point(5.0) - origin};
            TraversalStats stats;
            CAPTURE(k);
            check_same(ray, grid.closest_hit(ray, &stats), closest_hit(ray, list));
            REQUIRE(stats.primitive_tests <= static_cast<std::uint64_t>(primitive_count(list)));
        }
    }
}

TEST_CASE("UniformGrid::closest_hit: empty, single, coincident, flat and lopsided scenes",
          "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    PortableRandom random(7);
    const auto check_rays = [&](const PrimitiveList& list) {
        const UniformGrid grid(list);
        for (int k = 0; k < 300; ++k) {
            const Ray ray = k % 2 == 0 ? ray_from_outside(random) : ray_from_inside(random);
            CAPTURE(k);
            check_same(ray, grid.closest_hit(ray), closest_hit(ray, list));
        }
    };
    {
        INFO("no primitives");
        const std::optional<PrimitiveHit> hit =
            UniformGrid(PrimitiveList{}).closest_hit({{0, 0, 5}, {0, 0, -1}});
        CHECK_FALSE(hit);
    }
    {
        INFO("one sphere, one triangle");
        PrimitiveList sphere;
        sphere.spheres = {{{0.5, -0.5, 1}, 2.0}};
        check_rays(sphere);
        PrimitiveList triangle;
        triangle.triangles = {{{-3, -3, 0}, {3, -3, 1}, {0, 3, -1}}};
        check_rays(triangle);
    }
    {
        INFO("everything at one point");
        PrimitiveList stacked;
        for (int k = 0; k < 50; ++k)
            stacked.spheres.push_back({{1, 1, 1}, 0.5 + 0.05 * k});
        check_rays(stacked);
        PrimitiveList points;  // degenerate triangles: every test misses them
        for (int k = 0; k < 50; ++k)
            points.triangles.push_back({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}});
        check_rays(points);
    }
    {
        INFO("a flat scene: a 20 x 20 floor of triangles in z = 0");
        PrimitiveList floor;
        for (int i = 0; i < 20; ++i) {
            for (int j = 0; j < 20; ++j) {
                const Vec3 a(i - 10, j - 10, 0), b(i - 9, j - 10, 0), c(i - 9, j - 9, 0),
                    d(i - 10, j - 9, 0);
                floor.triangles.push_back({a, b, c});
                floor.triangles.push_back({a, c, d});
            }
        }
        check_rays(floor);
        const UniformGrid grid(floor);
        CHECK(grid.resolution().z == 1);
        for (int k = 0; k < 400; ++k) {  // straight down through edges and vertices
            const Ray ray{{0.5 * (k % 40) - 10, 0.5 * (k / 20) - 10, 3}, {0, 0, -1}};
            CAPTURE(k);
            check_same(ray, grid.closest_hit(ray), closest_hit(ray, floor));
        }
    }
    {
        INFO("a huge sphere beside small triangles");
        PrimitiveList lopsided = random_scene(random, 200);
        lopsided.spheres.push_back({{0, 0, -1e4 - 6}, 1e4});
        check_rays(lopsided);
    }
}

TEST_CASE(
    "UniformGrid::closest_hit: a zero direction, or a ray that misses the grid's box, visits no "
    "cell",
    "[stage4]") {
    PortableRandom random(8);
    const PrimitiveList list = random_scene(random, 100);
    const UniformGrid grid(list);
    TraversalStats stats;
    CHECK_FALSE(grid.closest_hit({{0, 0, 0}, {0, 0, 0}}, &stats));
    CHECK_FALSE(grid.closest_hit({{0, 0, 100}, {0, 0, 1}}, &stats));  // pointing away
    CHECK_FALSE(grid.closest_hit({{0, 100, 0}, {1, 0, 0}}, &stats));  // passing beside it
    CHECK(stats.nodes == 0);
    CHECK(stats.primitive_tests == 0);
}

TEST_CASE("UniformGrid: a ray that ends exactly at a wall between cells still finds it",
          "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    INFO(
        "A shadow ray to a point on a surface ends at t_max = that point's t. Walls lie in the "
        "planes between cells (x, y or z = n / 2 of a 6-cell grid); the ray's crossing of such a "
        "plane can round an ulp after the hit, so a walk that stops at t_max finds the wall only "
        "if the wall is listed in the cells on both sides of it: list each primitive in every "
        "cell its box, grown by the margin, overlaps (docs/stage4.md, \"Uniform grids\").");
    int asked = 0;
    for (const int n : {12, 16, 24}) {
        for (std::uint64_t seed = 0; seed < 10; ++seed) {
            PortableRandom random(seed, static_cast<std::uint64_t>(n));
            const auto lattice = [&] {
                const double x = static_cast<double>(random.integer(0, n));
                const double y = static_cast<double>(random.integer(0, n));
                const double z = static_cast<double>(random.integer(0, n));
                return Vec3(x, y, z);
            };
            // Two small triangles in opposite corners set the box to [0, n]^3: 80 primitives,
            // 6 cells a side, and n / 2 the plane between cells 3 and 4.
            const double size = n;
            PrimitiveList list;
            list.triangles.push_back({{0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}});
            list.triangles.push_back(
                {{size, size, size}, {size - 0.5, size, size}, {size, size - 0.5, size}});
            for (int k = 0; k < 78; ++k) {
                const int axis = static_cast<int>(random.integer(0, 2));
                const double plane = static_cast<double>(n / 2 * random.integer(0, 2));
                Vec3 p0 = lattice();
                Vec3 p1 = lattice();
                Vec3 p2 = lattice();
                p0[axis] = p1[axis] = p2[axis] = plane;
                list.triangles.push_back({p0, p1, p2});
            }
            const UniformGrid grid(list);
            for (int r = 0; r < 100; ++r) {
                const Triangle& wall = list.triangles[random.integer(2, 79)];
                const double a = static_cast<double>(random.integer(0, 4)) / 4.0;
                const double b =
                    static_cast<double>(random.integer(0, static_cast<std::int64_t>(4 - 4 * a))) /
                    4.0;
                const Vec3 target = wall.p0 + a * (wall.p1 - wall.p0) + b * (wall.p2 - wall.p0);
                Ray ray{lattice(), Vec3(0.0)};
                ray.direction = target - ray.origin;
                if (ray.direction == Vec3(0.0)) continue;
                const std::optional<PrimitiveHit> first = closest_hit(ray, list);
                if (!first || first->hit.t == ray.t_min) continue;
                ray.t_max = first->hit.t;
                ++asked;
                CAPTURE(n, seed, r);
                check_same(ray, grid.closest_hit(ray), first);
                INFO(text(ray));
                REQUIRE(grid.occluded(ray));
            }
        }
    }
    CHECK(asked > 2000);
}

TEST_CASE("UniformGrid::occluded: a grid of no primitives occludes nothing", "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    const bool occluded = UniformGrid(PrimitiveList{}).occluded({{0, 0, 5}, {0, 0, -1}});
    CHECK_FALSE(occluded);
}

TEST_CASE("UniformGrid::occluded: a zero direction visits no cell", "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    PortableRandom random(8);
    const UniformGrid grid(random_scene(random, 100));
    TraversalStats stats;
    const bool occluded = grid.occluded({{0, 0, 0}, {0, 0, 0}}, &stats);
    CHECK_FALSE(occluded);
    CHECK(stats.nodes == 0);
    CHECK(stats.primitive_tests == 0);
}

TEST_CASE("UniformGrid::occluded: agrees with closest_hit, before, at and after the first hit",
          "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    PortableRandom random(9);
    const PrimitiveList list = random_scene(random, 300);
    const UniformGrid grid(list);
    int hits = 0;
    for (int k = 0; k < 1000; ++k) {
        Ray ray = k % 2 == 0 ? ray_from_outside(random) : ray_from_inside(random);
        CAPTURE(k);
        INFO(text(ray));
        const std::optional<PrimitiveHit> first = closest_hit(ray, list);
        const bool occluded = grid.occluded(ray);
        REQUIRE(occluded == first.has_value());
        if (!first) continue;
        ++hits;
        for (const double cut : {0.5, 1.0, 2.0}) {  // t_max = first t is still a hit: closed
            ray.t_max = cut * first->hit.t;
            INFO("t_max cut to " << ray.t_max << ", " << cut << " times the first hit's t");
            const bool occluded_before = grid.occluded(ray);
            REQUIRE(occluded_before == closest_hit(ray, list).has_value());
        }
    }
    CHECK(hits > 200);
}

TEST_CASE(
    "UniformGrid::closest_hit: a ray that misses everything visits cells but tests few "
    "primitives",
    "[stage4]") {
    INFO(
        "125 spheres of radius 0.2 on the integer points of [0, 4]^3: 7 x 7 x 7 cells. The ray "
        "runs between the rows at y = z = 0.5, 0.7 from every centre, across the whole grid.");
    PrimitiveList lattice;
    for (int k = 0; k < 125; ++k)
        lattice.spheres.push_back({{k % 5, k / 5 % 5, k / 25}, 0.2});
    const UniformGrid grid(lattice);
    TraversalStats stats;
    CHECK_FALSE(grid.closest_hit({{-1, 0.5, 0.5}, {1, 0, 0}}, &stats));
    CHECK(stats.nodes >= 5);
    CHECK(stats.primitive_tests <= 125 / 10);  // brute force tests all 125
    // The walk ends where the ray does: t_max = 1.5 ends it at x = 0.5, in the second cell.
    TraversalStats short_ray;
    CHECK_FALSE(grid.closest_hit({{-1, 0.5, 0.5}, {1, 0, 0}, 0.0, 1.5}, &short_ray));
    CHECK(short_ray.nodes <= 3);
}

TEST_CASE("UniformGrid::closest_hit: a ray through an empty region tests no primitive",
          "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    INFO("Two walls of spheres, at x = 0 and x = 10; the ray crosses the gap between them.");
    const UniformGrid grid(two_walls_of_spheres());
    TraversalStats stats;
    CHECK_FALSE(grid.closest_hit({{5, -2, 2}, {0, 1, 0}}, &stats));
    // From below, above the left wall: it enters the grid at x = 2.9, in the gap, and leaves
    // through the top at x = 4.1. The walk starts where the ray enters, not above its origin.
    CHECK_FALSE(grid.closest_hit({{0, 2.5, -12}, {1, 0, 4}}, &stats));
    CHECK(stats.nodes > 0);
    CHECK(stats.primitive_tests == 0);
}

TEST_CASE("UniformGrid::occluded: a ray through an empty region tests no primitive", "[stage4]") {
    INFO(uses("UniformGrid", "grid_resolution, intersect_aabb, stage 3's functions"));
    INFO("Two walls of spheres, at x = 0 and x = 10; the ray crosses the gap between them.");
    const UniformGrid grid(two_walls_of_spheres());
    const Ray ray{{5, 2, -2}, {0, 0, 1}};
    INFO(text(ray));
    TraversalStats stats;
    const bool occluded = grid.occluded(ray, &stats);
    CHECK_FALSE(occluded);
    CHECK(stats.nodes > 0);
    CHECK(stats.primitive_tests == 0);
}
