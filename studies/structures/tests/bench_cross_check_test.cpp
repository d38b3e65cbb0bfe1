#include "studies/structures/cross_check.h"

#include "base/testing/catch.h"
#include "studies/structures/tests/bench_fakes.h"

using namespace raystep;
using raystep::testing::fake_candidate;
using raystep::testing::numbered_rays;

namespace {

BenchHit hit_on(std::size_t ray) {
    return {static_cast<std::uint32_t>(ray % 5), 0.5 * ray};
}

// Like hit_on but for rays 3 and 70: a miss, and another primitive at the same t.
BenchHit buggy_hit_on(std::size_t ray) {
    if (ray == 3) return {};
    if (ray == 70) return {99, 35.0};
    return hit_on(ray);
}

std::vector<StructureMeasurement> measure(const std::vector<BenchCandidate>& candidates) {
    MeasureOptions options;
    options.threads = 2;
    options.runs = 1;
    return measure_candidates(candidates, PrimitiveList{}, {{"a", "100 rays", numbered_rays(100)}},
                              options);
}

}  // namespace

TEST_CASE("compare_answers: counts differing rays among those both ran", "[bench]") {
    std::vector<BenchHit> all(12);
    for (std::size_t k = 0; k < all.size(); ++k)
        all[k] = hit_on(k);
    // Every 3rd ray: 0, 3, 6, 9, the one for ray 6 wrong
    std::vector<BenchHit> thirds{hit_on(0), hit_on(3), {7, 1.0}, hit_on(9)};

    const AnswerComparison c = compare_answers(all, 1, thirds, 3);
    CHECK(c.compared == 4);
    CHECK(c.differing == 1);
    CHECK(c.first_ray == 6);
    CHECK(c.first_a == hit_on(6));
    CHECK(c.first_b == BenchHit{7, 1.0});

    CHECK(compare_answers(all, 1, all, 1).differing == 0);
    CHECK(compare_answers(all, 1, {}, 1).compared == 0);
}

TEST_CASE("compare_answers: a miss and a hit differ, and t must be equal, not close", "[bench]") {
    const std::vector<BenchHit> a{{}, {1, 2.0}};
    const std::vector<BenchHit> b{{1, 2.0}, {1, 2.0000000000000004}};
    CHECK(compare_answers(a, 1, b, 1).differing == 2);
}

TEST_CASE("cross_check_lines: two fake structures that differ make a warning", "[bench]") {
    BenchCandidate embree = fake_candidate("Embree", [](std::size_t) { return BenchHit{}; });
    embree.baseline = true;
    const std::vector<StructureMeasurement> results =
        measure({fake_candidate("BVH SAH", hit_on), fake_candidate("grid", buggy_hit_on),
                 fake_candidate("BVH median", hit_on), embree});
    const std::vector<std::string> lines = cross_check_lines(results, 0);
    REQUIRE(lines.size() == 2);
    // The baseline works in float: never compared
    CHECK(lines[0] == "cross-check: the same hits as BVH SAH (BVH median on 100 rays)");
    CHECK(lines[1] ==
          "WARNING: grid differs from BVH SAH on 2 of 100 rays; first ray 3: a miss against "
          "primitive 3 at t = 1.5. Both must return closest_hit's answer: one of them has a bug.");
}

TEST_CASE(
    "cross_check_lines: agreement is one line, and one structure alone has nothing to compare",
    "[bench]") {
    CHECK(cross_check_lines(
              measure({fake_candidate("BVH SAH", hit_on), fake_candidate("grid", hit_on)}), 0) ==
          std::vector<std::string>{"cross-check: the same hits as BVH SAH (grid on 100 rays)"});
    CHECK(cross_check_lines(measure({fake_candidate("BVH SAH", hit_on)}), 0).empty());
}
