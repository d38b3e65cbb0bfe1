// Public tests for stage 4, the BVH. Run them with `ctest --preset student -L stage4`, one
// method's with `build/student/bin/raystep_stage4_tests "Bvh::occluded:*"`. Every test builds a
// Bvh first, so the constructor comes before the rest.
//
// Each test calls your code before its CHECKs: a stub ends the test case at its first call and
// is reported once. A failure prints the ray; where a test tries many rays, it stops at the first
// that fails.
//
// A BVH must give exactly closest_hit's answer: the same primitive and the same t, compared
// with ==. Both call the same stage-3 tests; only the order differs.

#include <cmath>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "base/testing/number_text.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/3_intersect/tests/hit_text.h"
#include "stages/4_accel/bvh.h"

using namespace raystep;
using raystep::testing::text;
using raystep::testing::uses;

namespace {

// n small random triangles and n / 4 spheres in [-5, 5]^3.
PrimitiveList random_scene(PortableRandom& random, int n) {
    PrimitiveList list;
    for (int k = 0; k < n; ++k) {
        const Vec3 c = random.point(5.0);
        const double s = random.uniform(0.05, 1.0);
        list.triangles.push_back(
            {c + s * random.point(1.0), c + s * random.point(1.0), c + s * random.point(1.0)});
    }
    for (int k = 0; k < n / 4; ++k)
        list.spheres.push_back({random.point(5.0), 0.5 * random.uniform(0.05, 1.0)});
    return list;
}

Ray random_ray(PortableRandom& random) {
    const Vec3 origin = random.point(8.0);
    return {origin, random.point(5.0) - origin};
}

// The BVH's answer is closest_hit's, bit for bit; a difference ends the test case.
void check_same(const Ray& ray, const std::optional<PrimitiveHit>& got,
                const std::optional<PrimitiveHit>& expected) {
    INFO(text(ray));
    INFO("The BVH finds " << text(got) << ", closest_hit " << text(expected));
    REQUIRE(got.has_value() == expected.has_value());
    if (!got) return;
    REQUIRE(got->kind == expected->kind);
    REQUIRE(got->index == expected->index);
    REQUIRE(got->hit.t == expected->hit.t);
}

const BvhSplit kSplits[] = {BvhSplit::median, BvhSplit::sah};

std::string split_name(BvhSplit split) {
    return split == BvhSplit::median ? "median" : "sah";
}

}  // namespace

TEST_CASE("Bvh::closest_hit: equals closest_hit on random scenes and rays", "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    for (const BvhSplit split : kSplits) {
        for (const int seed : {1, 2, 3}) {
            PortableRandom random(static_cast<std::uint64_t>(seed));
            const PrimitiveList list = random_scene(random, 400);
            const Bvh bvh(list, split);
            for (int k = 0; k < 500; ++k) {
                const Ray ray = random_ray(random);
                CAPTURE(split_name(split), seed, k);
                check_same(ray, bvh.closest_hit(ray), closest_hit(ray, list));
            }
        }
    }
}

TEST_CASE("Bvh::closest_hit: rays from inside the scene, axis-parallel rays, short rays",
          "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    PortableRandom random(4);
    const PrimitiveList list = random_scene(random, 300);
    for (const BvhSplit split : kSplits) {
        const Bvh bvh(list, split);
        for (int k = 0; k < 300; ++k) {
            CAPTURE(split_name(split), k);
            const Vec3 origin = random.point(4.0);
            Vec3 axis(0.0);
            axis[k % 3] = k % 2 == 0 ? 1.0 : -1.0;
            const Ray axis_ray{origin, axis};
            check_same(axis_ray, bvh.closest_hit(axis_ray), closest_hit(axis_ray, list));
            const Ray short_ray{origin, random.point(1.0), 0.0, 2.0};
            check_same(short_ray, bvh.closest_hit(short_ray), closest_hit(short_ray, list));
        }
    }
}

TEST_CASE("Bvh::closest_hit: ties go to the primitive closest_hit picks", "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    INFO(
        "Three copies of one triangle and a sphere touching its plane at the same t: closest_hit "
        "takes the sphere (spheres come first); among triangles, the lowest index.");
    PrimitiveList list;
    const Triangle t{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    list.triangles = {t, t, t};
    list.spheres = {{{0, 0, -1}, 1.0}};
    const Ray ray{{0, 0, 5}, {0, 0, -1}};
    for (const BvhSplit split : kSplits) {
        CAPTURE(split_name(split));
        const Bvh bvh(list, split);
        check_same(ray, bvh.closest_hit(ray), closest_hit(ray, list));
        list.spheres.clear();
        const Bvh no_sphere(list, split);
        const std::optional<PrimitiveHit> first = no_sphere.closest_hit(ray);
        check_same(ray, first, closest_hit(ray, list));
        REQUIRE(first);
        REQUIRE(first->index == 0);
        list.spheres = {{{0, 0, -1}, 1.0}};
    }
}

TEST_CASE("Bvh::closest_hit: rays through edges shared by the triangles of a grid", "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    INFO(
        "A 20 x 20 grid of unit squares in z = 0, two triangles each; rays straight down through "
        "edge midpoints and vertices, where two to six triangles meet.");
    PrimitiveList list;
    for (int i = 0; i < 20; ++i) {
        for (int j = 0; j < 20; ++j) {
            const Vec3 a(i, j, 0), b(i + 1, j, 0), c(i + 1, j + 1, 0), d(i, j + 1, 0);
            list.triangles.push_back({a, b, c});
            list.triangles.push_back({a, c, d});
        }
    }
    for (const BvhSplit split : kSplits) {
        const Bvh bvh(list, split);
        for (int k = 0; k < 400; ++k) {
            const double x = 0.5 * (k % 40);
            const double y = 0.5 * (k / 20);
            const Ray ray{{x, y, 3}, {0, 0, -1}};
            CAPTURE(split_name(split), x, y);
            check_same(ray, bvh.closest_hit(ray), closest_hit(ray, list));
        }
    }
}

TEST_CASE("Bvh::closest_hit: an empty scene, one primitive, primitives all at one point",
          "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    const Ray ray{{0, 0, 5}, {0, 0, -1}};
    for (const BvhSplit split : kSplits) {
        CAPTURE(split_name(split));
        const std::optional<PrimitiveHit> in_empty = Bvh(PrimitiveList{}, split).closest_hit(ray);
        REQUIRE_FALSE(in_empty);
        PrimitiveList one;
        one.spheres = {{{0, 0, 0}, 1.0}};
        check_same(ray, Bvh(one, split).closest_hit(ray), closest_hit(ray, one));
        PrimitiveList stacked;
        for (int k = 0; k < 50; ++k)
            stacked.spheres.push_back({{0, 0, 0}, 1.0 + 0.01 * k});
        check_same(ray, Bvh(stacked, split).closest_hit(ray), closest_hit(ray, stacked));
    }
}

TEST_CASE("Bvh::closest_hit: a list of planes only holds nothing, and never crashes", "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    PrimitiveList planes;
    planes.planes = {{{0, 0, 0}, {0, 0, 1}}, {{0, 0, 2}, {0, 1, 1}}};
    const Ray ray{{0, 0, 5}, {0, 0, -1}};
    INFO(
        "planes are unbounded: they stay outside the BVH (the renderer tests them beside it), so "
        "a list of planes alone gives a tree with no node at all");
    INFO(text(ray));
    for (const BvhSplit split : kSplits) {
        CAPTURE(split_name(split));
        const Bvh bvh(planes, split);
        const std::optional<PrimitiveHit> hit = bvh.closest_hit(ray);
        REQUIRE_FALSE(hit);
    }
}

TEST_CASE("Bvh::occluded: a list of planes only holds nothing, and never crashes", "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    PrimitiveList planes;
    planes.planes = {{{0, 0, 0}, {0, 0, 1}}, {{0, 0, 2}, {0, 1, 1}}};
    const Ray ray{{0, 0, 5}, {0, 0, -1}};
    INFO("planes stay outside the BVH: a list of planes alone gives a tree with no node");
    INFO(text(ray));
    for (const BvhSplit split : kSplits) {
        CAPTURE(split_name(split));
        const Bvh bvh(planes, split);
        const bool occluded = bvh.occluded(ray);
        REQUIRE_FALSE(occluded);
    }
}

TEST_CASE("Bvh::closest_hit: nothing before t_min, nothing after t_max", "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    INFO(
        "From z = 5 down the z axis: the sphere's front at t = 4.5 and its back at 5.5, the "
        "triangle at 7. From t_min = 6 only the triangle is left; up to t_max = 5 only the front.");
    PrimitiveList list;
    list.spheres = {{{0, 0, 0}, 0.5}};
    list.triangles = {{{-1, -1, -2}, {1, -1, -2}, {0, 1, -2}}};
    for (const BvhSplit split : kSplits) {
        CAPTURE(split_name(split));
        const Bvh bvh(list, split);
        const Ray late{{0, 0, 5}, {0, 0, -1}, 6.0, HUGE_VAL};
        INFO(text(late));
        const std::optional<PrimitiveHit> hit = bvh.closest_hit(late);
        REQUIRE(hit);
        REQUIRE(hit->kind == PrimitiveKind::triangle);
        REQUIRE(hit->hit.t == 7.0);
        const Ray inside{{0, 0, 5}, {0, 0, -1}, 5.0, 6.0};  // starts inside the sphere
        check_same(inside, bvh.closest_hit(inside), closest_hit(inside, list));
        const Ray short_ray{{0, 0, 5}, {0, 0, -1}, 0.0, 5.0};
        check_same(short_ray, bvh.closest_hit(short_ray), closest_hit(short_ray, list));
    }
}

TEST_CASE("Bvh: a ray that ends exactly at its hit still finds it", "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    INFO(
        "A shadow ray to a point on a surface ends at t_max = that point's t. The triangle's t and "
        "its box's entry are rounded separately, so the box can seem to start just after t_max: "
        "clip the search at t_max widened a little, never at t_max itself (docs/stage4.md, "
        "\"Walking a BVH\"). Axis-aligned triangles and spheres on a lattice; rays to the "
        "triangles' vertices and edges, and rays grazing a sphere where its box touches it.");
    // Scenes 0 to 39, and scene 163, whose ray 854 (origin (3, 8, 12), direction (6.5, -6, -3.5))
    // meets a wall whose t rounds below its box's entry by more than the slab test's own rounding
    std::vector<int> scenes(40);
    std::iota(scenes.begin(), scenes.end(), 0);
    scenes.push_back(163);
    int asked = 0;
    for (const int scene : scenes) {
        const int n = 4 + scene % 13;
        PortableRandom build(1000 + scene, 0);
        // x, then y, then z: drawn one statement at a time, since a compiler may evaluate a
        // call's arguments in any order, and then the rays would differ between compilers
        const auto lattice = [&](PortableRandom& random) {
            const double x = static_cast<double>(random.integer(0, n));
            const double y = static_cast<double>(random.integer(0, n));
            const double z = static_cast<double>(random.integer(0, n));
            return Vec3(x, y, z);
        };
        PrimitiveList list;
        for (int k = 0; k < 60; ++k) {
            const int axis = static_cast<int>(build.integer(0, 2));
            Vec3 p0 = lattice(build), p1 = lattice(build), p2 = lattice(build);
            p1[axis] = p0[axis];
            p2[axis] = p0[axis];
            list.triangles.push_back({p0, p1, p2});
        }
        for (int k = 0; k < 20; ++k)
            list.spheres.push_back({0.37 * lattice(build), 0.1 * build.integer(1, 9)});
        const Bvh bvh(list, BvhSplit::sah);
        PortableRandom random(2000 + scene, 0);
        for (int r = 0; r < 2000; ++r) {
            Vec3 origin;
            Vec3 target;
            if (r % 2 == 0) {
                const Triangle& t = list.triangles[random.integer(0, 59)];
                const double a = random.integer(0, 4) / 4.0;
                const double b = random.integer(0, static_cast<std::int64_t>(4 - 4 * a)) / 4.0;
                target = t.p0 + a * (t.p1 - t.p0) + b * (t.p2 - t.p0);
                const Vec3 corner = lattice(random);
                origin = corner + Vec3(static_cast<double>(random.integer(-2, 2)));
            } else {
                const Sphere& sphere = list.spheres[random.integer(0, 19)];
                const int axis = static_cast<int>(random.integer(0, 2));
                Vec3 side(0.0);
                side[axis] = random.integer(0, 1) ? sphere.radius : -sphere.radius;
                target = sphere.center + side;
                Vec3 along(0.0);
                along[(axis + 1 + random.integer(0, 1)) % 3] = 1.0;
                origin = target - 3.0 * along;
            }
            Ray ray{origin, target - origin};
            if (ray.direction == Vec3(0.0)) continue;
            const std::optional<PrimitiveHit> first = closest_hit(ray, list);
            if (!first || first->hit.t == ray.t_min) continue;
            ray.t_max = first->hit.t;
            ++asked;
            CAPTURE(scene, r);
            check_same(ray, bvh.closest_hit(ray), first);
            INFO(text(ray));
            REQUIRE(bvh.occluded(ray));
        }
    }
    CHECK(asked > 40000);
}

TEST_CASE("Bvh::occluded: nothing after the last hit", "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    INFO(
        "From z = 5 down the z axis: the sphere from t = 4.5 to 5.5, the triangle at 7. From t_min "
        "= 7.5 nothing is left.");
    PrimitiveList list;
    list.spheres = {{{0, 0, 0}, 0.5}};
    list.triangles = {{{-1, -1, -2}, {1, -1, -2}, {0, 1, -2}}};
    const Ray past{{0, 0, 5}, {0, 0, -1}, 7.5, HUGE_VAL};
    INFO(text(past));
    for (const BvhSplit split : kSplits) {
        CAPTURE(split_name(split));
        const Bvh bvh(list, split);
        const bool occluded = bvh.occluded(past);
        REQUIRE_FALSE(occluded);
    }
}

TEST_CASE("Bvh::occluded: agrees with closest_hit, before and after the first hit", "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    PortableRandom random(5);
    const PrimitiveList list = random_scene(random, 300);
    for (const BvhSplit split : kSplits) {
        const Bvh bvh(list, split);
        for (int k = 0; k < 300; ++k) {
            Ray ray = random_ray(random);
            CAPTURE(split_name(split), k);
            INFO(text(ray));
            const std::optional<PrimitiveHit> first = closest_hit(ray, list);
            const bool occluded = bvh.occluded(ray);
            REQUIRE(occluded == first.has_value());
            if (first) {
                ray.t_max = 0.5 * first->hit.t;  // stop short of it
                INFO("t_max cut to " << ray.t_max << ", half the first hit's t");
                const bool occluded_before = bvh.occluded(ray);
                REQUIRE(occluded_before == closest_hit(ray, list).has_value());
            }
        }
    }
}

TEST_CASE("Bvh::closest_hit: a ray through empty space visits few nodes and tests nothing",
          "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    PortableRandom random(6);
    const PrimitiveList list = random_scene(random, 1000);
    const Bvh bvh(list, BvhSplit::sah);
    TraversalStats stats;
    CHECK_FALSE(bvh.closest_hit({{0, 0, 100}, {0, 0, 1}}, &stats));  // pointing away
    CHECK(stats.primitive_tests == 0);
    TraversalStats through;
    const Ray ray = random_ray(random);
    bvh.closest_hit(ray, &through);
    CHECK(through.nodes > 0);
    CHECK(through.primitive_tests < 1250 / 4);  // far fewer than brute force's 1250
}

TEST_CASE("Bvh::closest_hit: the SAH tree is no slower to walk than the median tree", "[stage4]") {
    INFO(uses("Bvh", "intersect_aabb and stage 3's functions"));
    INFO(
        "Counted in nodes and tests, not seconds: over the same rays the SAH's estimate of the "
        "cost must not lose to the median split on a scene of clustered primitives.");
    PortableRandom random(7);
    PrimitiveList list = random_scene(random, 2000);
    for (int k = 0; k < 2000; ++k) {  // a dense cluster beside the rest
        const Vec3 c = Vec3(20, 0, 0) + random.point(0.5);
        list.triangles.push_back({c, c + Vec3(0.01, 0, 0), c + Vec3(0, 0.01, 0)});
    }
    const Bvh median(list, BvhSplit::median);
    const Bvh sah(list, BvhSplit::sah);
    TraversalStats median_cost;
    TraversalStats sah_cost;
    for (int k = 0; k < 2000; ++k) {
        const Ray ray = random_ray(random);
        median.closest_hit(ray, &median_cost);
        sah.closest_hit(ray, &sah_cost);
    }
    CAPTURE(median_cost.nodes, median_cost.primitive_tests, sah_cost.nodes,
            sah_cost.primitive_tests);
    CHECK(sah_cost.nodes + 2 * sah_cost.primitive_tests <=
          median_cost.nodes + 2 * median_cost.primitive_tests);
}

TEST_CASE(
    "Bvh::nodes: a tree from the root, each box holding what lies below it, every primitive in a "
    "leaf",
    "[stage4]") {
    PortableRandom random(11);
    const PrimitiveList list = random_scene(random, 300);
    const std::size_t count = list.spheres.size() + list.triangles.size();
    const auto box_of = [&](std::size_t id) {
        return id < list.spheres.size() ? bounds_of(list.spheres[id])
                                        : bounds_of(list.triangles[id - list.spheres.size()]);
    };
    const auto holds = [](const Aabb& outer, const Aabb& inner) {
        return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y &&
               outer.min.z <= inner.min.z && outer.max.x >= inner.max.x &&
               outer.max.y >= inner.max.y && outer.max.z >= inner.max.z;
    };
    for (const BvhSplit split : kSplits) {
        CAPTURE(split_name(split));
        const std::vector<BvhNodeData> nodes = Bvh(list, split).nodes();
        REQUIRE_FALSE(nodes.empty());
        std::vector<int> parents(nodes.size(), 0);
        std::vector<int> leaves_holding(count, 0);
        for (std::size_t k = 0; k < nodes.size(); ++k) {
            CAPTURE(k);
            REQUIRE((nodes[k].children.empty() || nodes[k].primitives.empty()));
            for (const std::size_t child : nodes[k].children) {
                REQUIRE(child < nodes.size());
                ++parents[child];
                REQUIRE(holds(nodes[k].box, nodes[child].box));
            }
            for (const std::size_t id : nodes[k].primitives) {
                REQUIRE(id < count);
                ++leaves_holding[id];
                REQUIRE(holds(nodes[k].box, box_of(id)));
            }
        }
        // Node 0 is the root: no one's child; every other node has exactly one parent
        REQUIRE(parents[0] == 0);
        for (std::size_t k = 1; k < nodes.size(); ++k) {
            CAPTURE(k);
            REQUIRE(parents[k] == 1);
        }
        for (std::size_t id = 0; id < count; ++id) {
            CAPTURE(id);
            REQUIRE(leaves_holding[id] >= 1);
        }
    }
    CHECK(Bvh(PrimitiveList{}, BvhSplit::sah).nodes().empty());
}
