#include "studies/structures/measurement.h"

#include <algorithm>
#include <mutex>
#include <set>
#include <stdexcept>

#include "base/errors/not_implemented.h"
#include "base/testing/catch.h"
#include "studies/structures/ray_chunks.h"
#include "studies/structures/tests/bench_fakes.h"

using namespace raystep;
using raystep::testing::fake_candidate;
using raystep::testing::numbered_rays;

namespace {

BenchHit candidate_hit(std::size_t ray) {
    return {static_cast<std::uint32_t>(ray % 7), 1.0 + ray};
}

MeasureOptions quick_options() {
    MeasureOptions options;
    options.threads = 3;
    options.runs = 1;
    return options;
}

}  // namespace

TEST_CASE("for_each_chunk: every index once, on one thread or several", "[bench]") {
    for (const int threads : {1, 2, 5}) {
        for (const std::size_t count : {std::size_t{0}, std::size_t{1}, std::size_t{1000}}) {
            CAPTURE(threads, count);
            std::vector<int> seen(count, 0);
            std::set<int> workers;
            std::mutex mutex;
            for_each_chunk(count, chunk_size(count), threads,
                           [&](std::size_t begin, std::size_t end, int worker) {
                               std::lock_guard<std::mutex> lock(mutex);
                               workers.insert(worker);
                               for (std::size_t k = begin; k < end; ++k)
                                   ++seen[k];
                           });
            CHECK(std::count(seen.begin(), seen.end(), 1) == static_cast<long>(count));
            for (const int worker : workers)
                CHECK((worker >= 0 && worker < threads));
        }
    }
}

TEST_CASE("for_each_chunk: the first exception comes back after the threads stop", "[bench]") {
    CHECK_THROWS_WITH(for_each_chunk(100, 10, 4,
                                     [](std::size_t begin, std::size_t, int) {
                                         if (begin == 50) throw std::runtime_error("chunk 5");
                                     }),
                      "chunk 5");
}

TEST_CASE("chunk_size: the same for every structure, 1 to 1024 rays", "[bench]") {
    CHECK(chunk_size(0) == 1);
    CHECK(chunk_size(100) == 1);
    CHECK(chunk_size(6400) == 100);
    CHECK(chunk_size(std::size_t{1} << 18) == 1024);
}

TEST_CASE("measure_candidates: answers, counts and times for every ray set", "[bench]") {
    const std::vector<RaySet> sets{{"a", "100 rays", numbered_rays(100)},
                                   {"b", "10 rays", numbered_rays(10)}};
    const std::vector<StructureMeasurement> results = measure_candidates(
        {fake_candidate("fake", candidate_hit)}, PrimitiveList{}, sets, quick_options());
    REQUIRE(results.size() == 1);
    const StructureMeasurement& m = results[0];
    CHECK(m.name == "fake");
    CHECK(m.failure.empty());
    REQUIRE(m.ray_sets.size() == 2);
    const RayMeasurement& a = m.ray_sets[0];
    CHECK(a.rays == 100);
    CHECK(a.stride == 1);
    CHECK(a.stats.nodes == 100);
    CHECK(a.stats.primitive_tests == 200);
    CHECK(a.seconds_one_thread > 0.0);
    CHECK(a.seconds_all_threads > 0.0);
    REQUIRE(a.answers.size() == 100);
    for (std::size_t k = 0; k < 100; ++k) {
        CAPTURE(k);
        REQUIRE(a.answers[k] == candidate_hit(k));
    }
    CHECK(m.ray_sets[1].rays == 10);
}

TEST_CASE("measure_candidates: a stub's row says so and the others are measured", "[bench]") {
    BenchCandidate stub = fake_candidate("grid", candidate_hit);
    stub.make = [](const PrimitiveList&) -> std::unique_ptr<BenchStructure> {
        throw_not_implemented(4, "UniformGrid", "Grids");
    };
    BenchCandidate broken = fake_candidate("broken", [](std::size_t ray) -> BenchHit {
        if (ray == 42) throw std::runtime_error("ray 42 is cursed");
        return {};
    });
    const std::vector<StructureMeasurement> results =
        measure_candidates({stub, broken, fake_candidate("fake", candidate_hit)}, PrimitiveList{},
                           {{"a", "100 rays", numbered_rays(100)}}, quick_options());
    REQUIRE(results.size() == 3);
    CHECK_THAT(results[0].failure,
               Catch::Matchers::StartsWith("not implemented: stage 4: UniformGrid"));
    CHECK(results[0].ray_sets.empty());
    CHECK(results[1].failure == "failed: ray 42 is cursed");
    CHECK(results[2].failure.empty());
    CHECK(results[2].ray_sets.size() == 1);
}

TEST_CASE("measure_candidates: a subsampled candidate keeps within its test budget", "[bench]") {
    BenchCandidate brute = fake_candidate("brute force", candidate_hit);
    brute.subsampled = true;
    BenchCandidate small = fake_candidate("small scenes only", candidate_hit);
    small.max_primitives = 2;

    PrimitiveList list;
    list.spheres.resize(10);
    MeasureOptions options = quick_options();
    options.test_budget = 250.0;  // 25 rays of 10 primitives: every 4th of 100
    const std::vector<StructureMeasurement> results =
        measure_candidates({brute, small}, list, {{"a", "100 rays", numbered_rays(100)}}, options);
    const RayMeasurement& r = results[0].ray_sets.at(0);
    CHECK(r.stride == 4);
    CHECK(r.rays == 25);
    CHECK(r.answers[3] == candidate_hit(12));
    CHECK(results[1].failure == "skipped: 10 primitives, over its limit of 2");
}

TEST_CASE("mrays_per_second: millions of rays per second, 0 for no time", "[bench]") {
    CHECK(mrays_per_second(2000000, 0.5) == Approx(4.0));
    CHECK(mrays_per_second(10, 0.0) == 0.0);
}
