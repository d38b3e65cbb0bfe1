// The probe's own count of primitive tests (grader/probe/stage3_test_count.cpp), which judges a
// stage-4 structure's work: on the reference probe, each ray's count must equal the reference
// structure's own TraversalStats on the same ray, which count one per stage-3 test. A link
// without the --wrap options counts nothing; a count that followed stage 3 into its own calls
// (intersect_triangle handing over to one of the lecture methods) counts too much.

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "grader/grade/probe_client.h"
#include "stages/4_accel/bvh.h"
#include "stages/4_accel/uniform_grid.h"

using namespace raystep;

namespace {

struct CountScene {
    PrimitiveList primitives;
    std::vector<Ray> rays;
};

CountScene count_scene() {
    CountScene scene;
    PortableRandom random(0xC0);
    for (int k = 0; k < 200; ++k) {
        const Vec3 c = random.point(1.0);
        scene.primitives.triangles.push_back({c, c + random.point(0.2), c + random.point(0.2)});
    }
    for (int k = 0; k < 40; ++k)
        scene.primitives.spheres.push_back({random.point(1.0), random.uniform(0.02, 0.1)});
    for (int k = 0; k < 50; ++k) {
        const Vec3 origin = 3.0 * random.unit_vector();
        scene.rays.push_back({origin, random.point(0.8) - origin});
    }
    return scene;
}

// The probe's count for each ray of the scene, from `call` ("bvh_work" or "grid_work").
std::vector<std::uint64_t> probe_counts(const CountScene& scene, const std::string& call,
                                        bool occluded) {
    probe::Json rays = probe::Json::array();
    for (const Ray& ray : scene.rays)
        rays.push_back(probe::ray(ray));
    const probe::Json args = {{"primitives", probe::primitive_list(scene.primitives)},
                              {"rays", rays},
                              {"split", "sah"},
                              {"occluded", occluded}};
    const grade::ProbeSession session =
        grade::ask_probe(RAYSTEP_REFERENCE_PROBE, {{call, args}}, grade::ProbeRunLimits{});
    REQUIRE(session.answers.size() == 1);
    REQUIRE(session.answers[0].kind == grade::ProbeAnswer::Kind::result);
    return session.answers[0].value.at("tests").get<std::vector<std::uint64_t>>();
}

template <class Structure>
std::vector<std::uint64_t> own_counts(const Structure& structure, const CountScene& scene,
                                      bool occluded) {
    std::vector<std::uint64_t> counts;
    for (const Ray& ray : scene.rays) {
        TraversalStats stats;
        if (occluded) {
            structure.occluded(ray, &stats);
        } else {
            structure.closest_hit(ray, &stats);
        }
        counts.push_back(stats.primitive_tests);
    }
    return counts;
}

}  // namespace

TEST_CASE("stage3_tests_counted: the probe counts each BVH test as the BVH's own stats do",
          "[grader]") {
    const CountScene scene = count_scene();
    const Bvh bvh(scene.primitives, BvhSplit::sah);
    for (const bool occluded : {false, true}) {
        CAPTURE(occluded);
        const std::vector<std::uint64_t> counted = probe_counts(scene, "bvh_work", occluded);
        CHECK(counted == own_counts(bvh, scene, occluded));
    }
}

TEST_CASE("stage3_tests_counted: the probe counts each grid test as the grid's own stats do",
          "[grader]") {
    const CountScene scene = count_scene();
    const UniformGrid grid(scene.primitives);
    const std::vector<std::uint64_t> counted = probe_counts(scene, "grid_work", false);
    CHECK(counted == own_counts(grid, scene, false));
    std::uint64_t total = 0;
    for (const std::uint64_t n : counted)
        total += n;
    CHECK(total > 0);
}
