// The chi-square p-value that the grader's statistical checks and the samplers' public tests take
// their verdicts from (base/math/chi_square.h), against published values and a numerical integral.

#include <cmath>
#include <limits>

#include "base/math/chi_square.h"
#include "base/testing/catch.h"
#include "base/testing/special_values.h"

using raystep::chi_square_p_value;
using raystep::pooled_chi_square;
using raystep::testing::kNaN;

TEST_CASE("chi_square_p_value: the tables' 5% points, and exp(-x/2) for two degrees", "[base]") {
    // Upper 5% points (Abramowitz and Stegun, table 26.8; scipy.stats.chi2.isf(0.05, k)).
    CHECK(chi_square_p_value(3.841458820694124, 1) == Approx(0.05).epsilon(1e-9));
    CHECK(chi_square_p_value(18.307038053275146, 10) == Approx(0.05).epsilon(1e-9));
    CHECK(chi_square_p_value(123.22522145336181, 99) == Approx(0.05).epsilon(1e-9));
    // Both sides of the switch between the series and the continued fraction at x = a + 1.
    for (double x : {0.5, 1.9, 2.0, 2.1, 4.0, 30.0, 100.0}) {
        CAPTURE(x);
        CHECK(chi_square_p_value(x, 2) == Approx(std::exp(-x / 2)).epsilon(1e-12));
    }
}

TEST_CASE("chi_square_p_value: the public tests' 1e-6 thresholds and a hundred degrees", "[base]") {
    // Stage 8's thresholds, and 102 at 100 degrees, against Simpson's rule on the density
    // (1.0011e-6 and 0.425605).
    CHECK(chi_square_p_value(56.49, 15) == Approx(1.0011e-6).epsilon(1e-3));
    CHECK(chi_square_p_value(131.37, 63) == Approx(1e-6).epsilon(0.01));
    CHECK(chi_square_p_value(102.0, 100) == Approx(0.425605).epsilon(1e-5));
}

TEST_CASE("chi_square_p_value: nothing is 1, infinity and NaN are 0 so that they fail", "[base]") {
    CHECK(chi_square_p_value(0.0, 99) == 1.0);
    CHECK(chi_square_p_value(std::numeric_limits<double>::infinity(), 99) == 0.0);
    CHECK(chi_square_p_value(kNaN, 99) == 0.0);
}

TEST_CASE("pooled_chi_square: Pearson's sum, bins expecting under 5 pooled into one", "[base]") {
    // Two full bins (10 against 8, 20 against 25) and three small ones pooled: 3 + 1 + 2 against
    // 2 + 2 + 1 = 6 against 5. Three cells, two degrees.
    const auto pooled = pooled_chi_square({10, 20, 3, 1, 2}, {8, 25, 2, 2, 1});
    CHECK(pooled.statistic == Approx(4.0 / 8 + 25.0 / 25 + 1.0 / 5));
    CHECK(pooled.degrees == 2);
}

TEST_CASE("pooled_chi_square: counts where nothing is expected make it infinite", "[base]") {
    const auto pooled = pooled_chi_square({10, 1}, {11, 0});
    CHECK(pooled.statistic == std::numeric_limits<double>::infinity());
    CHECK(chi_square_p_value(pooled.statistic, pooled.degrees) == 0.0);
}
