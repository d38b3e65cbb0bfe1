// The chi-square p-value that the samplers' tests (stage 8, stage 10) take their verdict from.

#include <cmath>

#include "base/testing/catch.h"
#include "base/testing/chi_square.h"

using raystep::testing::chi_square_p_value;

TEST_CASE("chi_square_p_value: with 2 degrees of freedom it is exp(-x / 2)", "[base]") {
    for (double x : {0.1, 1.0, 3.0, 10.0, 40.0, 100.0}) {
        CAPTURE(x);
        CHECK(chi_square_p_value(x, 2) == Approx(std::exp(-x / 2.0)).epsilon(1e-12));
    }
}

TEST_CASE("chi_square_p_value: 1 at 0, and the tables' quantiles", "[base]") {
    CHECK(chi_square_p_value(0.0, 10) == 1.0);
    // Upper 5% and 1e-6 quantiles (the latter stage 8's thresholds).
    CHECK(chi_square_p_value(3.841459, 1) == Approx(0.05).epsilon(1e-5));
    CHECK(chi_square_p_value(18.307038, 10) == Approx(0.05).epsilon(1e-5));
    CHECK(chi_square_p_value(56.49, 15) == Approx(1e-6).epsilon(0.01));
    CHECK(chi_square_p_value(131.37, 63) == Approx(1e-6).epsilon(0.01));
    // Both branches meet where the series hands over to the continued fraction, x / 2 = k / 2 + 1:
    // 0.0002 apart, where the density is 0.027, p differs by 1.3e-5 of itself.
    CHECK(chi_square_p_value(101.9999, 100) ==
          Approx(chi_square_p_value(102.0001, 100)).epsilon(3e-5));
    CHECK(chi_square_p_value(102.0, 100) == Approx(0.42560).epsilon(1e-4));
}
