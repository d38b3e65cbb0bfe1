// Public tests for stage 10, the weights of multiple importance sampling and Russian roulette.

#include <cmath>
#include <limits>

#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/vec3_matchers.h"
#include "stages/10_path_tracing/path_tracing.h"

using namespace raystep;
using raystep::testing::IsNear;

TEST_CASE("balance_heuristic: pdf / (pdf + other), the two weights summing to 1", "[stage10]") {
    CHECK_THAT(balance_heuristic(3.0, 1.0), IsNear(0.75, 1e-15));
    for (double a : {1e-300, 0.5, 2.0, 1e300}) {
        for (double b : {1e-300, 0.5, 2.0, 1e300}) {
            CAPTURE(a, b);
            CHECK_THAT(balance_heuristic(a, b) + balance_heuristic(b, a), IsNear(1.0, 1e-15));
        }
    }
    CHECK(balance_heuristic(0.0, 2.0) == 0.0);
    CHECK(balance_heuristic(2.0, 0.0) == 1.0);
    CHECK(balance_heuristic(0.0, 0.0) == 0.0);
}

TEST_CASE("power_heuristic: pdf^2 / (pdf^2 + other^2), summing to 1 with no overflow",
          "[stage10]") {
    CHECK_THAT(power_heuristic(3.0, 1.0), IsNear(0.9, 1e-15));
    // 1e200 squared overflows: the weights must still be numbers that sum to 1.
    for (double a : {1e-200, 0.5, 2.0, 1e200}) {
        for (double b : {1e-200, 0.5, 2.0, 1e200}) {
            CAPTURE(a, b);
            CHECK_THAT(power_heuristic(a, b) + power_heuristic(b, a), IsNear(1.0, 1e-15));
        }
    }
    CHECK(power_heuristic(0.0, 2.0) == 0.0);
    CHECK(power_heuristic(0.0, 0.0) == 0.0);
    CHECK(power_heuristic(std::numeric_limits<double>::infinity(), 1.0) == 1.0);
}

TEST_CASE("russian_roulette: the expected weight is the throughput", "[stage10]") {
    // The mean over u on a fine grid of [0, 1) is the expectation to within the grid's step.
    for (const Color& throughput : {Color(0.3, 0.1, 0.2), Color(0.9, 0.05, 0.5), Color(0.01)}) {
        CAPTURE(throughput);
        constexpr int kSteps = 100000;
        Color sum(0.0);
        for (int k = 0; k < kSteps; ++k) {
            if (const std::optional<Color> kept = russian_roulette(throughput, (k + 0.5) / kSteps))
                sum += *kept;
        }
        CHECK_THAT(sum / double(kSteps), IsNear(throughput, 1e-4));
    }
}

TEST_CASE("russian_roulette: goes on with probability max component, divided by it", "[stage10]") {
    const Color throughput(0.2, 0.5, 0.1);
    REQUIRE(russian_roulette(throughput, 0.49).has_value());
    CHECK_THAT(*russian_roulette(throughput, 0.49), IsNear(Color(0.4, 1.0, 0.2), 1e-15));
    CHECK_FALSE(russian_roulette(throughput, 0.5).has_value());
    CHECK_FALSE(russian_roulette(Color(0.0), 0.0).has_value());
    // A throughput of 1 or more always goes on, unchanged.
    CHECK(russian_roulette(Color(1.5, 0.2, 0.0), 0.999) == Color(1.5, 0.2, 0.0));
}
