#include "studies/sampling/noise_statistics.h"

#include <cmath>
#include <stdexcept>

#include "base/testing/catch.h"

using namespace raystep;

TEST_CASE("image_rmse: the root mean square over every pixel and channel", "[bench]") {
    Image reference(2, 1);
    Image image(2, 1);
    image.set(0, 0, Color(0.3, 0.0, 0.0));  // one channel of six off by 0.3
    CHECK(image_rmse(image, reference) == Approx(std::sqrt(0.09 / 6.0)).epsilon(1e-6));
    CHECK(image_rmse(reference, reference) == 0.0);
}

TEST_CASE("image_rmse: images of different sizes or of no pixels are refused", "[bench]") {
    CHECK_THROWS_AS(image_rmse(Image(2, 1), Image(1, 2)), std::invalid_argument);
    CHECK_THROWS_AS(image_rmse(Image(0, 0), Image(0, 0)), std::invalid_argument);
}

TEST_CASE("mean_and_spread: the sample standard deviation divides by n - 1", "[bench]") {
    const MeanSpread ms = mean_and_spread({1.0, 2.0, 3.0, 6.0});
    CHECK(ms.mean == Approx(3.0));
    // squares 4 + 1 + 0 + 9 = 14, over 3
    CHECK(ms.spread == Approx(std::sqrt(14.0 / 3.0)));
    CHECK(mean_and_spread({5.0}).spread == 0.0);
    CHECK_THROWS_AS(mean_and_spread({}), std::invalid_argument);
}

TEST_CASE("log_log_slope: the exponent of a power law, -0.5 for 1/sqrt(N)", "[bench]") {
    CHECK(log_log_slope({1, 4, 16, 64}, {0.2, 0.1, 0.05, 0.025}) == Approx(-0.5));
    CHECK(log_log_slope({1, 4, 16}, {1.0, 1.0 / 8.0, 1.0 / 64.0}) == Approx(-1.5));
    // Off the line: the least-squares fit through (0,0), (1,-1), (2,-1) in log2 units
    CHECK(log_log_slope({1, 2, 4}, {1.0, 0.5, 0.5}) == Approx(-0.5));
}

TEST_CASE("log_log_slope: one point, a zero, or a single x are refused", "[bench]") {
    CHECK_THROWS_AS(log_log_slope({1}, {1}), std::invalid_argument);
    CHECK_THROWS_AS(log_log_slope({1, 4}, {0.1, 0.0}), std::invalid_argument);
    CHECK_THROWS_AS(log_log_slope({1, 4}, {0.1, std::nan("")}), std::invalid_argument);
    CHECK_THROWS_AS(log_log_slope({4, 4}, {0.1, 0.2}), std::invalid_argument);
    CHECK_THROWS_AS(log_log_slope({1, 4, 16}, {0.1, 0.2}), std::invalid_argument);
}
