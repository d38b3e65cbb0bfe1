// Stage 4 checks: the BVH (both splits) and the grid must return exactly closest_hit's answer
// (same primitive, same t) on seeded scenes made to break them: random soups, shared edges met by
// axis-parallel rays, coincident primitives (ties), flat and degenerate ones, lists of one kind,
// empty lists and lists of planes only; rays with t_min > 0 and finite t_max in each, and shadow
// rays that end exactly at their hit; occluded must agree with the closest hit over the same
// interval. The expected answers come from the reference closest_hit, run here in the grader.
// Each structure check also counts the primitive tests the structure makes (stage4_work.cpp): one
// that is right but does brute force's work earns nothing. The slab test's entry and exit against
// the exact interval (stage4_slab_cases.cpp); grid_resolution against the handout's rule
// (stage4_grid_resolution_cases.cpp), both public: each case is judged by a data judge, which the
// student release runs on the same data. Speed: the submission's structure against the
// reference's on the same rays, timed from outside the probe.

#include <chrono>
#include <cmath>

#include "base/math/portable_random.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/data_judged.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grading/4_accel/accel_judges.h"
#include "grading/4_accel/accel_workloads.h"
#include "grading/4_accel/stage4_cases.h"
#include "stages/3_intersect/intersect.h"
#include "stages/4_accel/traversal.h"

namespace raystep::grade {

namespace {

struct AccelScene {
    std::string name;
    PrimitiveList primitives;
    std::vector<Ray> rays;
    /// The primitives built in C++, for a student's test; empty where they are too many to write
    /// out (the random scenes: hundreds of primitives from the grader's seeds).
    std::string code;
};

// [t_min, t_max] for ray k of a scene: a third start beyond 0, a third stop short, and every
// sixth does both, so that a leaf test or a walk that forgets either end is seen.
void bound_interval(PortableRandom& random, int k, Ray& ray) {
    if (k % 3 == 1 || k % 6 == 5) ray.t_min = random.uniform(0.2, 2.0);
    if (k % 3 == 2 || k % 6 == 5) ray.t_max = ray.t_min + random.uniform(0.1, 2.5);
}

// Small triangles and spheres in the cube [-1, 1]^3, met by rays from outside it and from inside
// it; three planes beside them, which the structure must leave out.
AccelScene random_soup(std::uint64_t seed) {
    PortableRandom random(seed);
    AccelScene s{"random soup", soup_primitives(random), {}, ""};
    for (int k = 0; k < 600; ++k) {
        // Half from outside the scene, half from inside it.
        const Vec3 origin = k % 2 ? random.point(1.0) : 3.0 * random.unit_vector();
        Ray ray{origin, random.point(1.0) - origin};
        bound_interval(random, k, ray);
        s.rays.push_back(ray);
    }
    return s;
}

// One kind of primitive only: every sphere or every triangle index must still be the list's.
AccelScene one_kind(std::uint64_t seed, bool spheres) {
    PortableRandom random(seed);
    AccelScene s{spheres ? "spheres only" : "triangles only", {}, {}, ""};
    for (int k = 0; k < 120; ++k) {
        const Vec3 c = random.point(1.0);
        if (spheres) {
            s.primitives.spheres.push_back({c, random.uniform(0.02, 0.2)});
        } else {
            s.primitives.triangles.push_back({c, c + random.point(0.3), c + random.point(0.3)});
        }
    }
    for (int k = 0; k < 150; ++k) {
        const Vec3 origin = k % 2 ? random.point(1.0) : 3.0 * random.unit_vector();
        Ray ray{origin, random.point(1.0) - origin};
        bound_interval(random, k, ray);
        s.rays.push_back(ray);
    }
    return s;
}

// A grid of quads sharing edges and vertices, met by axis-parallel rays through the shared edges:
// where slab tests with 0 * inf and children met at the same t go wrong. Rays from z = 5 meet the
// quads at t = 5 exactly, and some have t_min or t_max at 5 or an ulp beside it: both ends of
// [t_min, t_max] belong to it.
AccelScene shared_edges() {
    AccelScene s{
        "shared edges, axis-parallel rays",
        {},
        {},
        "PrimitiveList primitives;\n"
        "for (int i = 0; i < 8; ++i) {\n"
        "    for (int j = 0; j < 8; ++j) {\n"
        "        const Vec3 a(i, j, 0), b(i + 1, j, 0), c(i + 1, j + 1, 0), d(i, j + 1, 0);\n"
        "        primitives.triangles.push_back({a, b, c});\n"
        "        primitives.triangles.push_back({a, c, d});\n"
        "    }\n"
        "}\n"};
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            const Vec3 a(i, j, 0), b(i + 1, j, 0), c(i + 1, j + 1, 0), d(i, j + 1, 0);
            s.primitives.triangles.push_back({a, b, c});
            s.primitives.triangles.push_back({a, c, d});
        }
    }
    const double above = std::nextafter(5.0, HUGE_VAL);
    const double below = std::nextafter(5.0, 0.0);
    const double ends[][2] = {{0.0, HUGE_VAL}, {5.0, HUGE_VAL}, {above, HUGE_VAL},
                              {0.0, 5.0},      {0.0, below},    {5.0, 5.0}};
    for (int i = 0; i <= 8; ++i) {
        for (int j = 0; j <= 8; ++j) {
            const auto& [t_min, t_max] = ends[(i + j) % 6];
            s.rays.push_back({Vec3(i, j, 5), Vec3(0, 0, -1), t_min, t_max});
            s.rays.push_back({Vec3(i + 0.5, j, 5), Vec3(0, 0, -1), t_min, t_max});
            s.rays.push_back({Vec3(i, -1, 0), Vec3(0, 1, 0)});  // in the plane: misses
        }
    }
    return s;
}

// Coincident and stacked primitives: equal t on different primitives, which only comes_before's
// order settles; degenerate triangles and zero-radius spheres, which are misses.
AccelScene ties_and_degenerates(std::uint64_t seed) {
    PortableRandom random(seed);
    AccelScene s{"ties and degenerate primitives", {}, {}, ""};
    for (int k = 0; k < 40; ++k) {
        const Vec3 c = random.point(1.0);
        const Triangle t{c, c + Vec3(0.3, 0, 0), c + Vec3(0, 0.3, 0)};
        s.primitives.triangles.push_back(t);
        s.primitives.triangles.push_back(t);  // the same twice
        s.primitives.triangles.push_back({c, c + Vec3(0.3, 0, 0), c + Vec3(0.6, 0, 0)});  // flat
        s.primitives.spheres.push_back({c, 0.1});
        s.primitives.spheres.push_back({c, 0.1});
        s.primitives.spheres.push_back({c + Vec3(0, 0, 0.5), 0.0});
    }
    for (int k = 0; k < 400; ++k) {
        const Vec3 target =
            s.primitives.triangles[static_cast<std::size_t>(3 * (k % 40))].p0 +
            Vec3(random.uniform(0, 0.15), random.uniform(0, 0.15), random.uniform(0, 0.15));
        const Vec3 origin = target + 2.0 * random.unit_vector();
        Ray r{origin, target - origin};
        if (k % 4 == 0) r.t_max = 0.9;                       // stop short of some hits
        if (k % 4 == 1) r.t_min = random.uniform(0.8, 1.0);  // start near them
        s.rays.push_back(r);
    }
    return s;
}

// Two walls a thousandth either side of the plane between a 2-cell grid's halves, met by rays
// along x from 2^46 away, where t rounds to multiples of 2^-6: both walls' hits and the ray's
// crossing of the plane all round to t = 2^46 + 1. The wall beyond the plane (triangle 0) wins
// the tie by comes_before, but it lies more than the grid's margin from the plane, so it is
// listed only in the next cell: a walk must go on while the next cell begins at or before the
// best t, not only strictly before. Two small triangles in far corners set the grid's box to
// [0, 2]^3.
AccelScene tie_across_a_cell_boundary() {
    AccelScene s{"a tie across a cell boundary, from far away",
                 {},
                 {},
                 "PrimitiveList primitives;\n"
                 "primitives.triangles.push_back({{1.002, 0, 0}, {1.002, 2, 0}, {1.002, 0, 2}});\n"
                 "primitives.triangles.push_back({{0.998, 0, 0}, {0.998, 2, 0}, {0.998, 0, 2}});\n"
                 "primitives.triangles.push_back({{0, 2, 2}, {0, 1.9, 2}, {0, 2, 1.9}});\n"
                 "primitives.triangles.push_back({{2, 2, 2}, {2, 1.9, 2}, {2, 2, 1.9}});\n"};
    s.primitives.triangles = {{{1.002, 0, 0}, {1.002, 2, 0}, {1.002, 0, 2}},
                              {{0.998, 0, 0}, {0.998, 2, 0}, {0.998, 0, 2}},
                              {{0, 2, 2}, {0, 1.9, 2}, {0, 2, 1.9}},
                              {{2, 2, 2}, {2, 1.9, 2}, {2, 2, 1.9}}};
    const double far = -0x1p46;
    const double tie = 0x1p46 + 1.0;
    for (const double y : {0.25, 0.5, 0.75}) {
        for (const double z : {0.25, 0.5}) {
            s.rays.push_back({{far, y, z}, {1, 0, 0}});
            s.rays.push_back({{far, y, z}, {1, 0, 0}, 0.0, tie});
        }
    }
    return s;
}

// Two walls an ulp apart on either side of the plane x = 2 between cells of a grid over [0, 4]^3
// (20 primitives: four cells of exactly 1 a side), met by rays from beyond x = 0 through points
// of them. The wall on the plane (triangle 0) touches the near cells only at the plane; the other
// (triangle 1) lies wholly in them. Both hits mostly round to the same t, where triangle 0 wins
// the tie, and the ray's crossing of the plane often rounds an ulp later: a grid that lists
// triangle 0 only in the far cells stops at the near cells' end with triangle 1. So does a BVH
// that enters a box only when it starts at or before the best t, with no slack, where the walls
// are in different nodes: the box of triangle 0 starts at that crossing. Sixteen small triangles
// out of the rays' way, and two in opposite corners that set the box, make up the 20.
AccelScene walls_an_ulp_apart(std::uint64_t seed) {
    PortableRandom random(seed);
    AccelScene s{
        "two walls an ulp apart on a cell boundary",
        {},
        {},
        "PrimitiveList primitives;\n"
        "const double before = std::nextafter(2.0, 0.0);\n"
        "primitives.triangles.push_back({{2, 0.25, 0.25}, {2, 3.75, 0.25}, {2, 0.25, 3.75}});\n"
        "primitives.triangles.push_back({{before, 0.25, 0.25}, {before, 3.75, 0.25}, "
        "{before, 0.25, 3.75}});\n"
        "primitives.triangles.push_back({{0, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0}});\n"
        "primitives.triangles.push_back({{4, 4, 4}, {3.9, 4, 4}, {4, 3.9, 4}});\n"
        "for (int i = 0; i < 16; ++i) {\n"
        "    const Vec3 c(0.25 + 0.225 * i, 3.5, 3.5);\n"
        "    primitives.triangles.push_back({c, c + Vec3(0.1, 0, 0), c + Vec3(0, 0.1, 0.1)});\n"
        "}\n"};
    const double before = std::nextafter(2.0, 0.0);
    s.primitives.triangles = {{{2, 0.25, 0.25}, {2, 3.75, 0.25}, {2, 0.25, 3.75}},
                              {{before, 0.25, 0.25}, {before, 3.75, 0.25}, {before, 0.25, 3.75}},
                              {{0, 0, 0}, {0.1, 0, 0}, {0, 0.1, 0}},
                              {{4, 4, 4}, {3.9, 4, 4}, {4, 3.9, 4}}};
    for (int i = 0; i < 16; ++i) {
        const Vec3 c(0.25 + 0.225 * i, 3.5, 3.5);
        s.primitives.triangles.push_back({c, c + Vec3(0.1, 0, 0), c + Vec3(0, 0.1, 0.1)});
    }
    for (int k = 0; k < 300; ++k) {
        const Vec3 target(2, random.uniform(1.0, 2.0), random.uniform(1.0, 2.0));
        const double x = k % 2 ? random.uniform(-3.0, -0.5) : random.uniform(-40.0, -10.0);
        const Vec3 origin(x, target.y + random.uniform(-0.3, 0.3),
                          target.z + random.uniform(-0.3, 0.3));
        s.rays.push_back({origin, target - origin});
    }
    return s;
}

// A point with whole coordinates in [0, n]^3, drawn x, then y, then z: one statement each, since
// a call's arguments may be evaluated in any order and the point would differ between compilers.
Vec3 lattice_point(PortableRandom& random, int n) {
    const double x = static_cast<double>(random.integer(0, n));
    const double y = static_cast<double>(random.integer(0, n));
    const double z = static_cast<double>(random.integer(0, n));
    return Vec3(x, y, z);
}

// A point of the triangle at quarter steps of its edges: a vertex, a point of an edge or inside.
Vec3 quarter_point(PortableRandom& random, const Triangle& triangle) {
    const double a = static_cast<double>(random.integer(0, 4)) / 4.0;
    const double b =
        static_cast<double>(random.integer(0, static_cast<std::int64_t>(4 - 4 * a))) / 4.0;
    return triangle.p0 + a * (triangle.p1 - triangle.p0) + b * (triangle.p2 - triangle.p0);
}

// A shadow ray from `origin` aimed at `target` on a surface: it ends exactly at the t of the first
// hit, t_max = that t, as a renderer's ray to a point it has found does. Nothing when it has no
// direction, hits nothing, or hits at t_min (a ray of no length).
void add_ray_ending_at_its_hit(AccelScene& scene, const Vec3& origin, const Vec3& target) {
    Ray ray{origin, target - origin};
    if (ray.direction == Vec3(0.0)) return;
    const std::optional<PrimitiveHit> first = structure_answer(ray, scene.primitives);
    if (!first || first->hit.t == ray.t_min) return;
    ray.t_max = first->hit.t;
    scene.rays.push_back(ray);
}

// Walls lying in the planes between a grid's cells, met by shadow rays that end exactly at their
// hit. Two small triangles in opposite corners set the box to [0, n]^3 and 78 walls with lattice
// vertices lie in the planes x, y or z = 0, n / 2 or n: 80 primitives, 6 cells a side by the
// handout's rule, so n / 2 is the plane between cells 3 and 4 however a grid grows its box by a
// margin both ways. A wall in that plane touches the cells on both sides only at the plane; the
// ray's crossing of it can round an ulp after the hit, and a walk that stops there (the ray ends
// at the hit) finds the wall only if it is listed on the near side too: a grid that lists each
// primitive in the cells of its exact box misses it.
AccelScene walls_on_cell_planes(std::uint64_t seed, int n) {
    PortableRandom random(seed);
    const double size = n;
    AccelScene s{"walls on the planes between cells, rays that end at their hit", {}, {}, ""};
    s.primitives.triangles = {
        {{0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}},
        {{size, size, size}, {size - 0.5, size, size}, {size, size - 0.5, size}}};
    for (int k = 0; k < 78; ++k) {
        const int axis = static_cast<int>(random.integer(0, 2));
        const double plane = static_cast<double>(n / 2 * random.integer(0, 2));
        Vec3 p0 = lattice_point(random, n), p1 = lattice_point(random, n),
             p2 = lattice_point(random, n);
        p0[axis] = p1[axis] = p2[axis] = plane;
        s.primitives.triangles.push_back({p0, p1, p2});
    }
    for (int k = 0; k < 100; ++k) {
        const Triangle& wall =
            s.primitives.triangles[static_cast<std::size_t>(random.integer(2, 79))];
        const Vec3 target = quarter_point(random, wall);
        const double offset = static_cast<double>(random.integer(-2, 2));
        const Vec3 corner = lattice_point(random, n);
        add_ray_ending_at_its_hit(s, corner + Vec3(offset), target);
    }
    return s;
}

// Axis-aligned triangles and spheres on a lattice, scene `scene` of the public test "Bvh: a ray
// that ends exactly at its hit" (its seeds and lattice size), met by shadow rays that end exactly
// at their hit: rays to the triangles' vertices and edges, and rays along an axis grazing a sphere
// where its box touches it. A triangle's t and its box's entry round separately, so the box can
// seem to start just after t_max: a BVH that clips its walk at t_max itself, or at t_max widened
// by the slab test's rounding alone, misses the hit (scene 163 has such a ray, its 854th).
AccelScene lattice_shadow_rays(int scene) {
    const int n = 4 + scene % 13;
    PortableRandom build(static_cast<std::uint64_t>(1000 + scene));
    AccelScene s{"lattice triangles and spheres, rays that end at their hit", {}, {}, ""};
    for (int k = 0; k < 60; ++k) {
        const int axis = static_cast<int>(build.integer(0, 2));
        Vec3 p0 = lattice_point(build, n), p1 = lattice_point(build, n),
             p2 = lattice_point(build, n);
        p1[axis] = p0[axis];
        p2[axis] = p0[axis];
        s.primitives.triangles.push_back({p0, p1, p2});
    }
    for (int k = 0; k < 20; ++k)
        s.primitives.spheres.push_back(
            {0.37 * lattice_point(build, n), 0.1 * static_cast<double>(build.integer(1, 9))});
    PortableRandom random(static_cast<std::uint64_t>(2000 + scene));
    for (int k = 0; k < 2000; ++k) {
        if (k % 2 == 0) {
            const Triangle& triangle =
                s.primitives.triangles[static_cast<std::size_t>(random.integer(0, 59))];
            const Vec3 target = quarter_point(random, triangle);
            const Vec3 corner = lattice_point(random, n);
            const double offset = static_cast<double>(random.integer(-2, 2));
            add_ray_ending_at_its_hit(s, corner + Vec3(offset), target);
            continue;
        }
        const Sphere& sphere =
            s.primitives.spheres[static_cast<std::size_t>(random.integer(0, 19))];
        const int axis = static_cast<int>(random.integer(0, 2));
        Vec3 side(0.0);
        side[axis] = random.integer(0, 1) ? sphere.radius : -sphere.radius;
        Vec3 along(0.0);
        along[(axis + 1 + static_cast<int>(random.integer(0, 1))) % 3] = 1.0;
        const Vec3 target = sphere.center + side;
        add_ray_ending_at_its_hit(s, target - 3.0 * along, target);
    }
    return s;
}

// Nothing to build over: no primitives at all, or only planes, which stay outside the structure.
// Every ray misses. Asked last: a structure that crashes here loses these rays' cases, not the
// others'.
AccelScene nothing_to_hold(bool planes) {
    AccelScene s{planes ? "planes only" : "no primitives",
                 {},
                 {},
                 planes ? "PrimitiveList primitives;\n"
                          "primitives.planes.push_back({{0, 0, 0}, {0, 0, 1}});\n"
                          "primitives.planes.push_back({{0, 0, 2}, {0, 1, 1}});\n"
                        : "PrimitiveList primitives;\n"};
    if (planes) {
        s.primitives.planes.push_back({{0, 0, 0}, {0, 0, 1}});
        s.primitives.planes.push_back({{0, 0, 2}, {0, 1, 1}});
    }
    s.rays = {{{0, 0, 5}, {0, 0, -1}},
              {{0.5, 0.25, 5}, {0.1, 0.2, -1}, 1.0, 10.0},
              {{0, 0, 0}, {1, 0, 0}},
              {{3, -2, 1}, {0, 1, 0}}};
    return s;
}

std::vector<AccelScene> scenes() {
    return {random_soup(0xB7A1),
            shared_edges(),
            ties_and_degenerates(0x7135),
            one_kind(0x5F1, true),
            one_kind(0x7A1, false),
            tie_across_a_cell_boundary(),
            walls_an_ulp_apart(0xB0DE),
            walls_on_cell_planes(0xCE11, 12),
            walls_on_cell_planes(0xCE12, 16),
            walls_on_cell_planes(0xCE13, 24),
            lattice_shadow_rays(163),
            nothing_to_hold(false),
            nothing_to_hold(true)};
}

// How a student builds the scene in a test of their own, or what it is where it is not written
// out.
std::string scene_code(const AccelScene& scene) {
    if (!scene.code.empty()) return scene.code;
    return "// primitives: the grader's scene \"" + scene.name + "\", " +
           std::to_string(scene.primitives.triangles.size()) + " triangles, " +
           std::to_string(scene.primitives.spheres.size()) + " spheres and " +
           std::to_string(scene.primitives.planes.size()) +
           " planes from its own seed; compare with closest_hit over its spheres and triangles\n";
}

std::string structure_code(const std::string& call, const std::string& split, bool occluded,
                           const Ray& ray) {
    const std::string structure = call == "bvh" ? "Bvh(primitives, BvhSplit::" + split + ")"
                                                : std::string("UniformGrid(primitives)");
    return structure + (occluded ? ".occluded(" : ".closest_hit(") + cpp(ray) + ")";
}

// One ray's answer from the structure, exactly the reference closest_hit's.
Judgement judge_ray(const ProbeAnswer& answer, const AccelScene& scene, std::size_t k,
                    bool occluded) {
    const std::optional<PrimitiveHit> expected = structure_answer(scene.rays[k], scene.primitives);
    if (occluded) {
        const std::string expected_text = expected ? "occluded" : "not occluded";
        if (answer.kind != ProbeAnswer::Kind::result) return wrong(expected_text, "");
        if (!answer.value.is_boolean()) return wrong(expected_text, "not a boolean");
        const bool got = answer.value.get<bool>();
        return got == expected.has_value()
                   ? right()
                   : wrong(expected_text, got ? "occluded" : "not occluded");
    }
    const auto same = [&](const std::optional<PrimitiveHit>& got) {
        return got.has_value() == expected.has_value() &&
               (!got || (got->kind == expected->kind && got->index == expected->index &&
                         got->hit.t == expected->hit.t));
    };
    return judge_result(answer, primitive_hit_text(expected), probe::primitive_hit_from, same,
                        primitive_hit_text);
}

// One structure over every scene: each ray's answer must be exactly the reference's. The
// structure is built once per scene and asked about all its rays; each ray is a case.
CheckMeasure measure_structure(const GradingContext& context, const BuiltProbe& probe,
                               const std::string& id, const std::string& call,
                               const std::string& split, bool occluded) {
    const std::vector<AccelScene> all = scenes();
    std::vector<CaseBatch> batches;
    for (const AccelScene& scene : all) {
        const auto query = [&scene, call, split, occluded](std::vector<Ray> rays) {
            const probe::StructureQuestion question{
                scene.primitives, std::move(rays),
                split.empty() ? std::nullopt : std::optional<std::string>(split), occluded};
            return probe::query(call == "bvh" ? probe::bvh_call : probe::grid_call, question);
        };
        CaseBatch batch{query(scene.rays),
                        [&scene, query](std::size_t k) { return query({scene.rays[k]}); },
                        {}};
        const std::string code = scene_code(scene);
        for (std::size_t k = 0; k < scene.rays.size(); ++k) {
            batch.cases.push_back(
                {scene.name + ", ray " + std::to_string(k) + ": " + ray_text(scene.rays[k]),
                 {},
                 [&scene, k, occluded](const ProbeAnswer& answer) {
                     return judge_ray(answer, scene, k, occluded);
                 },
                 code + structure_code(call, split, occluded, scene.rays[k])});
        }
        batches.push_back(std::move(batch));
    }
    // A student's structure may build slowly (a full SAH sweep): more room than a unit check.
    ProbeRunLimits limits;
    limits.cpu_seconds = 30;
    limits.wall = std::chrono::seconds(60);
    CheckMeasure measure = run_batched_cases(context, id, probe, batches, limits);
    // Nothing to count for a stub or a build that failed; and a structure that ran out of time
    // would only run out again on the work scene, doubling the grade's time for nothing
    if (context.only_case || measure.outcome == Outcome::not_implemented ||
        measure.outcome == Outcome::did_not_compile || measure.outcome == Outcome::timed_out ||
        measure.grader_error) {
        return measure;
    }

    // Right answers earn their points only from a structure that does less work than brute force
    const CheckMeasure work = measure_work(context, probe, {id, call, split});
    for (const auto& [name, value] : work.metrics)
        measure.metrics[name] = value;
    if (work.outcome == Outcome::passed) {
        measure.summary += "; " + work.summary;
        return measure;
    }
    measure.outcome = Outcome::failed;
    measure.fraction = 0.0;
    measure.summary += "; but " + work.summary;
    measure.counterexamples.insert(measure.counterexamples.begin(), work.counterexamples.begin(),
                                   work.counterexamples.end());
    return measure;
}

// The structure's speed against the reference's on the same rays, in the same run, scored by the
// kernel's account of each probe's CPU time; and against no structure at all (stage 3's
// closest_hit over every primitive, run by the reference probe), reported. The rays change every
// pass, by a jitter drawn from the grade's own seed, so a structure that remembers answers gains
// nothing and no digest can be written in beforehand. A structure whose hits differ from
// the reference's earns nothing for speed: fast and wrong is not fast. Nor does one that does not
// do a structure's work (measure_work).
CheckMeasure measure_speed(const GradingContext& context, const BuiltProbe& probe,
                           const std::string& structure) {
    if (!probe.program) return not_compiled(probe);
    CheckMeasure measure;
    // Many rays through a scene big enough that the structure is what costs, made by each probe
    // (stage4_work_scenes.h). Each ray also as a shadow ray cut short before the scene (every
    // origin lies 3 from the middle, the scene within 1.8 of it): the walk's occluded is timed too
    constexpr int kRays = 20000;
    constexpr int kPasses = 20;
    constexpr int kBruteForceRays = 1000;  // each costs a test per primitive: a few suffice
    probe::WorkloadQuestion walk;
    walk.speed = probe::SpeedScene{kRays};
    walk.split = "sah";
    walk.jitter = timed_walk_jitter(context);
    const ProbeQuery query = probe::query(
        structure == "bvh" ? probe::bvh_workload_call : probe::grid_workload_call, walk);
    const std::vector<WorkloadTime> timed =
        timed_workloads({{context.reference_probe, query}, {*probe.program, query}}, kPasses);
    const WorkloadTime& reference = timed[0];
    const WorkloadTime& student = timed[1];
    if (!student.not_implemented.empty()) {
        measure.outcome = Outcome::not_implemented;
        measure.summary = student.not_implemented;
        return measure;
    }
    if (!student.answered || !reference.answered) {
        measure.outcome = Outcome::failed;
        measure.summary =
            !student.answered
                ? "the " + structure + " did not answer the workload (a crash or a timeout)"
                : "the reference did not answer the workload";
        return measure;
    }
    if (student.checksum != reference.checksum || !student.same_answers) {
        measure.outcome = Outcome::failed;
        measure.summary = "the " + structure +
                          " answered the timed rays otherwise than the reference (the digest of "
                          "its answers is " +
                          student.checksum.dump() + ", the reference's " +
                          reference.checksum.dump() +
                          "): a structure with wrong answers earns nothing for speed";
        return measure;
    }
    const CheckMeasure work = measure_work(
        context, probe, {"stage4.speed." + structure, structure, structure == "bvh" ? "sah" : ""});
    if (work.outcome != Outcome::passed) {
        measure.outcome = Outcome::failed;
        measure.summary =
            "a structure that does not do a structure's work earns nothing for speed: " +
            work.summary;
        measure.counterexamples = work.counterexamples;
        return measure;
    }
    probe::WorkloadQuestion brute_force_walk = walk;
    brute_force_walk.split.reset();
    brute_force_walk.speed = probe::SpeedScene{kBruteForceRays};
    const WorkloadTime brute_force =
        timed_workload(context.reference_probe,
                       probe::query(probe::brute_force_workload_call, brute_force_walk), 1);
    const double ratio = reference.seconds / student.seconds;
    const double per_ray = student.seconds / (double(kPasses) * kRays);
    const double brute_force_ratio =
        brute_force.answered ? brute_force.seconds / kBruteForceRays / per_ray : 0.0;
    measure.fraction = std::min(1.0, ratio);
    measure.metrics = {{"speed against the reference", ratio},
                       {"speed against brute force", brute_force_ratio},
                       {"reference CPU seconds", reference.seconds},
                       {"submission CPU seconds", student.seconds},
                       {"timed rounds", static_cast<double>(student.rounds)}};
    const WorkScene scene = speed_scene(0);
    char text[260];
    std::snprintf(text, sizeof text,
                  " traced %d rays through %zu primitives %d times, new rays every pass, at %.2f "
                  "times the reference's speed in CPU time (best of %d rounds) and %.0f times "
                  "brute force's",
                  kRays, scene.primitives.triangles.size() + scene.primitives.spheres.size(),
                  kPasses, ratio, student.rounds, brute_force_ratio);
    measure.summary = "the " + structure + text;
    measure.outcome = Outcome::passed;
    return measure;
}

// The names of the unit checks, shared by the grader's check and the release's case file.
constexpr const char* kSlabName =
    "intersect_aabb's entry and exit against the exact interval, edges and corners included";
constexpr const char* kGridResolutionName =
    "grid_resolution against the handout's rule, thin and flat boxes included";

}  // namespace

std::optional<PrimitiveHit> structure_answer(const Ray& ray, const PrimitiveList& primitives) {
    PrimitiveList held = primitives;
    held.planes.clear();
    return closest_hit(ray, held);
}

PublicCheck stage4_slab_public_check() {
    return {"stage4.unit.slab", 4, "unit", kSlabName, slab_cases()};
}

PublicCheck stage4_grid_resolution_public_check() {
    return {"stage4.unit.grid_resolution", 4, "unit", kGridResolutionName, grid_resolution_cases()};
}

std::vector<CheckDefinition> stage4_checks() {
    // The checks of one structure share the timed walk of its work (stage4_work.cpp): the first
    // measures it, and the others are measured_by that one.
    const auto structure = [](const std::string& id, const std::string& name,
                              const std::string& call, const std::string& split, bool occluded,
                              const std::string& measured_by) {
        return CheckDefinition{id,
                               4,
                               "oracle",
                               name,
                               [=](const GradingContext& context, const BuiltProbe& probe) {
                                   return measure_structure(context, probe, id, call, split,
                                                            occluded);
                               },
                               measured_by};
    };
    return {
        {"stage4.unit.slab", 4, "unit", kSlabName,
         [](const GradingContext& c, const BuiltProbe& p) {
             return run_cases(c, "stage4.unit.slab", p, data_judged_cases(slab_cases()));
         }},
        {"stage4.unit.grid_resolution", 4, "unit", kGridResolutionName,
         [](const GradingContext& c, const BuiltProbe& p) {
             return run_cases(c, "stage4.unit.grid_resolution", p,
                              data_judged_cases(grid_resolution_cases()));
         }},
        structure(
            "stage4.oracle.bvh_sah",
            "the SAH BVH's closest hit, exactly closest_hit's, with less work than brute force",
            "bvh", "sah", false, ""),
        structure("stage4.oracle.bvh_median",
                  "the median BVH's closest hit, exactly closest_hit's, with less work than brute "
                  "force",
                  "bvh", "median", false, "stage4.oracle.bvh_sah"),
        structure("stage4.oracle.bvh_occluded",
                  "the BVH's occluded, as the closest hit says, with less work than brute force",
                  "bvh", "sah", true, "stage4.oracle.bvh_sah"),
        structure("stage4.oracle.grid",
                  "the grid's closest hit, exactly closest_hit's, with less work than brute force",
                  "grid", "", false, ""),
        structure("stage4.oracle.grid_occluded",
                  "the grid's occluded, as the closest hit says, with less work than brute force",
                  "grid", "", true, "stage4.oracle.grid"),
        {"stage4.speed.bvh", 4, "speed",
         "the SAH BVH's speed against the reference's and brute force's, on the same rays",
         [](const GradingContext& c, const BuiltProbe& p) { return measure_speed(c, p, "bvh"); }},
        {"stage4.speed.grid", 4, "speed",
         "the grid's speed against the reference's and brute force's, on the same rays",
         [](const GradingContext& c, const BuiltProbe& p) { return measure_speed(c, p, "grid"); }},
    };
}

}  // namespace raystep::grade
