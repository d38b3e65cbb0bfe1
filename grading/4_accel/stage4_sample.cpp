// Stage 4's sample for the student release: the queries the "stage4.oracle" checks ask (the BVH
// with either split and the grid, closest hit and occluded), on one small scene drawn from seeds
// those checks do not use, each answer decided by the reference's brute force (structure_answer)
// when the release is written. The grader's checks also take the structure as data and time its
// walk, which only its probe can (grading/4_accel/accel_workloads.h): the sample judges answers
// alone, and says so.
//
// The t of a hit. The grader runs a structure on the reference's stage 3 and demands brute
// force's t bit for bit; `raystep grade` runs it on the student's own stage 3, whose t may round
// differently (the corpus model's Cramer finds 0.99999999999999978 where the reference finds 1).
// So the sample takes a t within kTTolerance of the reference's: far above the few ulps of t near
// 1 that any right stage 3 reaches on these well-shaped primitives, and far below kEndMargin, the
// least distance from either end of a ray's [t_min, t_max] at which its answer may change (no
// ray is kept whose answer changes when either end moves by that much), so that a stage 3 that
// rounds differently cannot change which answer is right.

#include <algorithm>

#include "app/grade/value_text.h"
#include "base/math/portable_random.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/data_judged.h"
#include "grader/grade/checks/stage_checks.h"
#include "grading/4_accel/accel_judges.h"
#include "grading/4_accel/stage4_cases.h"

namespace raystep::grade {

namespace {

using probe::Json;

constexpr std::uint64_t kSceneSeed = 0xB7A1 + kSampleSeedOffset;
constexpr std::uint64_t kRaySeed = 0x7135 + kSampleSeedOffset;

constexpr double kTTolerance = 1e-9;
constexpr double kEndMargin = 0.01;

// A few small triangles and spheres in [-1, 1]^3, the first triangle twice (a tie, which only
// comes_before's order settles), and a plane, which the structure must leave out.
PrimitiveList sample_scene() {
    PortableRandom random(kSceneSeed, 0);
    PrimitiveList list;
    for (int k = 0; k < 4; ++k) {
        const Vec3 c = random.point(1.0);
        list.triangles.push_back({c, c + random.point(0.4), c + random.point(0.4)});
    }
    list.triangles.insert(list.triangles.begin() + 1, list.triangles.front());
    for (int k = 0; k < 2; ++k)
        list.spheres.push_back({random.point(1.0), random.uniform(0.1, 0.3)});
    list.planes.push_back({random.point(1.0), random.unit_vector()});
    return list;
}

// The same answer: both misses, or hits on the same primitive.
bool same_primitive(const std::optional<PrimitiveHit>& a, const std::optional<PrimitiveHit>& b) {
    return a.has_value() == b.has_value() && (!a || (a->kind == b->kind && a->index == b->index));
}

// Whether the ray's answer stays the same with either end of [t_min, t_max] moved by kEndMargin,
// inwards or outwards.
bool settled(const Ray& ray, const PrimitiveList& list) {
    const std::optional<PrimitiveHit> answer = structure_answer(ray, list);
    for (const double move : {-kEndMargin, kEndMargin}) {
        Ray start = ray;
        start.t_min = std::max(0.0, ray.t_min + move);
        Ray end = ray;
        end.t_max = ray.t_max + move;
        if (!same_primitive(structure_answer(start, list), answer) ||
            !same_primitive(structure_answer(end, list), answer)) {
            return false;
        }
    }
    return true;
}

// Six rays, ray k aimed from outside the scene at a point of primitive k (a triangle's centroid
// or a sphere's centre), so that most rays hit; a third start beyond 0, a third stop short, one
// does both, so that a walk that forgets either end of [t_min, t_max] is seen. A ray whose answer
// is not settled is drawn again from the same generator.
std::vector<Ray> sample_rays(const PrimitiveList& list) {
    constexpr std::size_t kRays = 6;
    std::vector<Ray> rays;
    for (std::size_t k = 0; k < kRays; ++k) {
        PortableRandom random(kRaySeed, k);
        const Vec3 target =
            k < list.triangles.size()
                ? (list.triangles[k].p0 + list.triangles[k].p1 + list.triangles[k].p2) / 3.0
                : list.spheres[k - list.triangles.size()].center;
        Ray ray;
        do {
            const Vec3 origin = target + 2.5 * random.unit_vector();
            ray = {origin, target - origin};
            if (k % 3 == 1 || k == 5) ray.t_min = random.uniform(0.2, 0.9);
            if (k % 3 == 2 || k == 5) ray.t_max = ray.t_min + random.uniform(0.1, 0.8);
        } while (!settled(ray, list));
        rays.push_back(ray);
    }
    return rays;
}

// The scene as a student writes it in a test of their own.
std::string scene_code(const PrimitiveList& list) {
    std::string code = "PrimitiveList primitives;\n";
    for (const Triangle& t : list.triangles) {
        code += "primitives.triangles.push_back({" + cpp(t.p0) + ", " + cpp(t.p1) + ", " +
                cpp(t.p2) + "});\n";
    }
    for (const Sphere& s : list.spheres)
        code += "primitives.spheres.push_back(" + cpp(s) + ");\n";
    for (const Plane& p : list.planes)
        code += "primitives.planes.push_back({" + cpp(p.point) + ", " + cpp(p.normal) + "});\n";
    return code;
}

struct SampleQuery {
    std::string call;   ///< "bvh" or "grid"
    std::string split;  ///< the BVH's split; empty for the grid
    bool occluded = false;
};

}  // namespace

PublicCheck stage4_sample_check() {
    const PrimitiveList list = sample_scene();
    const std::vector<Ray> rays = sample_rays(list);
    const std::string code = scene_code(list);
    const std::vector<SampleQuery> queries = {
        {"bvh", "sah", false}, {"bvh", "median", false}, {"bvh", "sah", true},
        {"grid", "", false},   {"grid", "", true},
    };
    std::vector<PublicCase> cases;
    for (const SampleQuery& q : queries) {
        const std::string structure = q.call == "bvh" ? "Bvh(primitives, BvhSplit::" + q.split + ")"
                                                      : std::string("UniformGrid(primitives)");
        const std::string what = q.call == "bvh" ? "the " + q.split + " BVH" : "the grid";
        for (std::size_t k = 0; k < rays.size(); ++k) {
            Json args = {{"primitives", probe::primitive_list(list)},
                         {"rays", Json::array({probe::ray(rays[k])})},
                         {"occluded", q.occluded}};
            if (!q.split.empty()) args["split"] = q.split;
            const std::optional<PrimitiveHit> expected = structure_answer(rays[k], list);
            cases.push_back({what + (q.occluded ? "'s occluded" : "'s closest hit") +
                                 ", sample scene, ray " + std::to_string(k) + ": " +
                                 ray_text(rays[k]),
                             {q.call, args},
                             q.occluded ? structure_occluded_judge(expected.has_value())
                                        : structure_hit_judge(expected, kTTolerance),
                             code + structure + (q.occluded ? ".occluded(" : ".closest_hit(") +
                                 cpp(rays[k]) + ")"});
        }
    }
    return sample_check(4,
                        "the BVH's and the grid's closest hit and occluded against brute force: "
                        "the same primitive, t within 1e-9 (on your own stage 3; the grader, on "
                        "the reference's, demands the very t, checks the structure your nodes() or "
                        "cells() hand over and times your walk)",
                        std::move(cases));
}

}  // namespace raystep::grade
