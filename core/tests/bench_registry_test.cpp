#include "core/bench/baseline_registry.h"

#include <algorithm>

#include "core/testing/catch.h"
#include "core/tests/bench_fakes.h"

using namespace raystep;

namespace {

// Registered the way grader/embree registers Embree: by a static object, before main.
const BaselineRegistration registration(
    raystep::testing::fake_candidate("Fakebree 1.0", [](std::size_t) { return BenchHit{}; }));

}  // namespace

TEST_CASE("registered_baselines: lists a baseline registered by a static object", "[bench]") {
    const std::vector<BenchCandidate>& baselines = registered_baselines();
    const auto found =
        std::find_if(baselines.begin(), baselines.end(),
                     [](const BenchCandidate& c) { return c.name == "Fakebree 1.0"; });
    REQUIRE(found != baselines.end());
    CHECK(found->baseline);
    REQUIRE(found->make);
    CHECK(found->make(PrimitiveList{}) != nullptr);
}

TEST_CASE("register_baseline: marks the candidate as the baseline and keeps the order", "[bench]") {
    const std::size_t before = registered_baselines().size();
    register_baseline(
        raystep::testing::fake_candidate("Late", [](std::size_t) { return BenchHit{}; }));
    REQUIRE(registered_baselines().size() == before + 1);
    CHECK(registered_baselines().back().name == "Late");
    CHECK(registered_baselines().back().baseline);
}
