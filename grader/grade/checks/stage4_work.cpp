// A structure earns its points by doing less work than brute force. The work is counted where a
// submission cannot fake it: its stage-4 probe takes stage 3 from the reference, so every primitive
// test the structure makes is a call into stage 3's public functions, and the probe counts those
// calls itself (grader/probe/stage3_test_count.cpp; closest_hit over a list counts as a test per
// primitive). The structure's own TraversalStats are never read. The reference structure's count
// on the same scene and rays comes from the reference, run here in the grader.
//
// No ray may cost more tests than the structure holds primitives: each is tested at most once
// per query (a grid lists a primitive in every cell it overlaps, and must not test it in each).
//
// The rays are fresh (their own seed, asked once each), so a structure that remembers the answers
// to rays it has seen gains nothing. The allowance over all the rays: kWorkAllowance times the
// reference's tests, or a test per kBruteForceShare primitives per ray, whichever is more. The
// first keeps a structure near the reference's quality; the second is room for a right structure
// of a plainer design (a median split where the reference prices SAH cuts, larger leaves, a
// coarser grid), whose count on a scene where the reference needs a handful of tests can be many
// times the reference's and still a small share of brute force's. Brute force makes a test per
// primitive per ray, kBruteForceShare times the floor, and fails by that margin
// (docs/measurements/stage4-work.md has the counts).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <optional>

#include "base/math/portable_random.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage4_cases.h"
#include "stages/4_accel/bvh.h"
#include "stages/4_accel/uniform_grid.h"

namespace raystep::grade {

namespace {

using probe::Json;

constexpr double kWorkAllowance = 4.0;
constexpr double kBruteForceShare = 16.0;
constexpr std::uint64_t kWorkSeed = 0x3017C;
constexpr int kTriangles = 1500;
constexpr int kSpheres = 150;
constexpr int kRays = 400;

struct WorkScene {
    std::string name;
    PrimitiveList primitives;
    std::vector<Ray> rays;
};

// Small primitives strewn through a cube, met by rays from a sphere around it; a quarter of the
// rays start beyond 0 and a quarter stop short, so that a walk must keep to [t_min, t_max].
WorkScene work_scene() {
    WorkScene scene;
    scene.name = "the work scene (" + std::to_string(kTriangles) + " triangles and " +
                 std::to_string(kSpheres) + " spheres from seed " + std::to_string(kWorkSeed) + ")";
    PortableRandom random(kWorkSeed);
    for (int k = 0; k < kTriangles; ++k) {
        const Vec3 c = random.point(1.0);
        scene.primitives.triangles.push_back({c, c + random.point(0.1), c + random.point(0.1)});
    }
    for (int k = 0; k < kSpheres; ++k)
        scene.primitives.spheres.push_back({random.point(1.0), random.uniform(0.01, 0.08)});
    for (int k = 0; k < kRays; ++k) {
        const Vec3 origin = 3.0 * random.unit_vector();
        Ray ray{origin, random.point(0.8) - origin};
        if (k % 4 == 1) ray.t_min = random.uniform(0.3, 0.8);
        if (k % 4 == 2) ray.t_max = random.uniform(0.5, 1.2);
        scene.rays.push_back(ray);
    }
    return scene;
}

// Four squares of two triangles each, stacked 0.1 apart over [0, 10]^2, and rays between them,
// parallel to them: each ray meets nothing, and crosses cells that all list the same triangles. A
// structure that tests a primitive once per cell it lists it in tests each several times.
WorkScene stacked_quads() {
    WorkScene scene;
    scene.name = "four stacked squares of two triangles, rays between them";
    for (int level = 0; level < 4; ++level) {
        const double z = 0.1 * level;
        const Vec3 a(0, 0, z), b(10, 0, z), c(10, 10, z), d(0, 10, z);
        scene.primitives.triangles.push_back({a, b, c});
        scene.primitives.triangles.push_back({a, c, d});
    }
    for (int level = 0; level < 3; ++level) {
        const double z = 0.1 * level + 0.05;
        for (int k = 0; k < 10; ++k) {
            const double across = 0.5 + k;
            scene.rays.push_back({Vec3(-1, across, z), Vec3(1, 0, 0)});
            scene.rays.push_back({Vec3(across, 11, z), Vec3(0, -1, 0)});
            scene.rays.push_back({Vec3(-1, -1 + 0.3 * k, z), Vec3(1, 0.9, 0)});
        }
    }
    return scene;
}

// The counts of an answer to a work query with `rays` rays, or nullopt when it is not one.
std::optional<std::vector<std::uint64_t>> counts_from(const ProbeAnswer& answer, std::size_t rays) {
    const Json& value = answer.value;
    const bool readable = answer.kind == ProbeAnswer::Kind::result && value.is_object() &&
                          value.contains("tests") && value.at("tests").is_array() &&
                          value.at("tests").size() == rays &&
                          std::all_of(value.at("tests").begin(), value.at("tests").end(),
                                      [](const Json& n) { return n.is_number_unsigned(); }) &&
                          value.contains("hits") && value.at("hits").is_number_unsigned();
    if (!readable) return std::nullopt;
    return value.at("tests").get<std::vector<std::uint64_t>>();
}

// The reference structure's tests for each ray, as its TraversalStats count them: the reference
// is trusted, and it counts one per call of a stage-3 test, as the probe does.
std::vector<std::uint64_t> reference_tests(const WorkScene& scene, const WorkQuery& query) {
    std::vector<std::uint64_t> tests;
    const auto count = [&](const auto& structure) {
        for (const Ray& ray : scene.rays) {
            TraversalStats stats;
            if (query.occluded) {
                structure.occluded(ray, &stats);
            } else {
                structure.closest_hit(ray, &stats);
            }
            tests.push_back(stats.primitive_tests);
        }
    };
    if (query.call == "bvh") {
        count(Bvh(scene.primitives, query.split == "median" ? BvhSplit::median : BvhSplit::sah));
    } else {
        count(UniformGrid(scene.primitives));
    }
    return tests;
}

// Why a run gave no readable answer, in a few words.
std::string why_unanswered(const ProbeSession& session, const ProbeAnswer& answer) {
    if (!answer.message.empty()) return answer.message;
    if (session.run.timed_out) return "it ran out of time";
    if (session.run.signal != 0)
        return "it crashed with signal " + std::to_string(session.run.signal);
    return "no readable answer";
}

CheckMeasure failed(std::string summary) {
    CheckMeasure measure;
    measure.outcome = Outcome::failed;
    measure.summary = std::move(summary);
    return measure;
}

}  // namespace

CheckMeasure measure_work(const GradingContext& context, const BuiltProbe& probe,
                          const WorkQuery& query) {
    if (!probe.program) return not_compiled(probe);
    const WorkScene scenes[] = {work_scene(), stacked_quads()};
    std::vector<ProbeQuery> queries;
    for (const WorkScene& scene : scenes) {
        Json rays = Json::array();
        for (const Ray& ray : scene.rays)
            rays.push_back(probe::ray(ray));
        Json args = {{"primitives", probe::primitive_list(scene.primitives)},
                     {"rays", rays},
                     {"occluded", query.occluded}};
        if (!query.split.empty()) args["split"] = query.split;
        queries.push_back({query.call + "_work", args});
    }
    ProbeRunLimits limits;
    limits.cpu_seconds = 30;
    limits.wall = std::chrono::seconds(60);
    const ProbeSession session = ask_probe(*probe.program, queries, limits);
    std::vector<std::vector<std::uint64_t>> counted;
    std::size_t hits = 0;
    for (std::size_t s = 0; s < std::size(scenes); ++s) {
        const ProbeAnswer& answer = session.answers[s];
        std::optional<std::vector<std::uint64_t>> tests =
            counts_from(answer, scenes[s].rays.size());
        if (!tests) {
            return failed(
                "the structure did not answer the rays whose primitive tests are "
                "counted (" +
                why_unanswered(session, answer) + ")");
        }
        counted.push_back(std::move(*tests));
        hits += answer.value.at("hits").get<std::size_t>();
    }

    // No ray may cost more tests than there are primitives: each is tested at most once
    for (std::size_t s = 0; s < std::size(scenes); ++s) {
        const WorkScene& scene = scenes[s];
        const std::uint64_t held =
            scene.primitives.spheres.size() + scene.primitives.triangles.size();
        const auto most = std::max_element(counted[s].begin(), counted[s].end());
        if (*most <= held) continue;
        CheckMeasure measure =
            failed("the structure tested the same primitive more than once in one query (" +
                   std::to_string(*most) + " tests of " + std::to_string(held) +
                   " primitives for one ray), so it earns nothing for its answers. A primitive "
                   "listed in several cells or nodes must be tested once per query: keep a "
                   "mailbox of the primitives this query has tested, as docs/stage4.md's "
                   "\"Mailboxing\" section shows");
        const std::size_t k = static_cast<std::size_t>(most - counted[s].begin());
        measure.counterexamples.push_back(
            {scene.name + ", ray " + std::to_string(k) + ": " + ray_text(scene.rays[k]),
             "at most " + std::to_string(held) + " primitive tests, one per primitive",
             std::to_string(*most) + " primitive tests: some primitive tested more than once",
             context.reproduce + " --check " + query.check_id,
             "// count the stage-3 calls your structure makes for " + cpp(scene.rays[k])});
        return measure;
    }

    // Against the reference and brute force on the strewn scene
    const WorkScene& scene = scenes[0];
    const std::vector<std::uint64_t>& tests = counted[0];
    const std::vector<std::uint64_t> reference = reference_tests(scene, query);
    const std::uint64_t brute_force =
        scene.primitives.spheres.size() + scene.primitives.triangles.size();
    const auto allowed = [brute_force](double reference_tests) {
        return std::max(kWorkAllowance * reference_tests, double(brute_force) / kBruteForceShare);
    };
    std::uint64_t student_total = 0;
    std::uint64_t reference_total = 0;
    std::size_t dearest = 0;
    double dearest_excess = -HUGE_VAL;
    for (std::size_t k = 0; k < scene.rays.size(); ++k) {
        student_total += tests[k];
        reference_total += reference[k];
        const double excess = double(tests[k]) - allowed(double(reference[k]));
        if (excess > dearest_excess) {
            dearest_excess = excess;
            dearest = k;
        }
    }
    const double per_ray = double(student_total) / double(scene.rays.size());
    const double reference_per_ray = double(reference_total) / double(scene.rays.size());
    char text[240];
    std::snprintf(text, sizeof text,
                  "%.1f primitive tests per ray through %llu primitives, where the reference makes "
                  "%.1f and brute force %llu",
                  per_ray, static_cast<unsigned long long>(brute_force), reference_per_ray,
                  static_cast<unsigned long long>(brute_force));
    if (hits > 0 && student_total == 0) {
        return failed(
            "the structure answered " + std::to_string(hits) +
            " rays with a hit without testing a primitive through stage 3's functions "
            "(intersect_sphere, intersect_triangle, closest_hit), the tests the grader counts");
    }
    CheckMeasure measure;
    measure.metrics = {{"primitive tests per ray", per_ray},
                       {"reference's primitive tests per ray", reference_per_ray},
                       {"brute force's primitive tests per ray", double(brute_force)}};
    if (per_ray <= allowed(reference_per_ray)) {
        measure.outcome = Outcome::passed;
        measure.fraction = 1.0;
        measure.summary = text;
        return measure;
    }
    measure.outcome = Outcome::failed;
    char allowance[120];
    std::snprintf(allowance, sizeof allowance, ": more than the %.1f a structure may make",
                  allowed(reference_per_ray));
    measure.summary = std::string(text) + allowance + ", so it earns nothing for its answers";
    const Ray& ray = scene.rays[dearest];
    measure.counterexamples.push_back(
        {scene.name + ", ray " + std::to_string(dearest) + ": " + ray_text(ray),
         "at most " +
             std::to_string(static_cast<std::uint64_t>(allowed(double(reference[dearest])))) +
             " primitive tests (the reference makes " + std::to_string(reference[dearest]) + ")",
         std::to_string(tests[dearest]) + " primitive tests",
         context.reproduce + " --check " + query.check_id,
         "// count the stage-3 calls your structure makes for " + cpp(ray)});
    return measure;
}

}  // namespace raystep::grade
