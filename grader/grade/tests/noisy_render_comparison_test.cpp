// Noisy renders against a converged reference (app/compare/noisy_render_comparison.h) on
// synthetic images: noise of one mean passes, a bias in part of the image fails there and only
// there, noise-free images agree within the floor, a NaN fails its tile.

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "app/compare/noisy_render_comparison.h"
#include "base/math/portable_random.h"
#include "base/testing/catch.h"

using namespace raystep;

namespace {

constexpr int kWidth = 64;
constexpr int kHeight = 48;
constexpr int kTile = 8;
constexpr double kBound = 4.0;
constexpr double kFloor = 1e-4;

// `count` renders from seed `seed`: each pixel 0.5 plus uniform noise of width `noise`, plus `bias`
// where x < kWidth / 2.
std::vector<Image> noisy_renders(std::uint64_t seed, int count, double bias, double noise = 0.2) {
    std::vector<Image> renders;
    for (int k = 0; k < count; ++k) {
        PortableRandom random(seed, static_cast<std::uint64_t>(k));
        Image image(kWidth, kHeight);
        for (int j = 0; j < kHeight; ++j) {
            for (int i = 0; i < kWidth; ++i) {
                const double shift = i < kWidth / 2 ? bias : 0.0;
                image.set(i, j,
                          Color(0.5 + shift + noise * (random.unit() - 0.5),
                                0.3 + shift + noise * (random.unit() - 0.5), 0.1 + shift));
            }
        }
        renders.push_back(image);
    }
    return renders;
}

}  // namespace

TEST_CASE("compare_noisy_renders: renders of one mean at other seeds agree", "[grader]") {
    // 48 tiles of 3 channels at 4 standard errors: 0.01 tiles apart expected per comparison, so
    // over 20 seeds at most a couple.
    int apart = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        CAPTURE(seed);
        const NoisyComparison c =
            compare_noisy_renders(noisy_renders(seed, 8, 0.0), noisy_renders(1000 + seed, 16, 0.0),
                                  kTile, kBound, kFloor);
        CHECK(c.tiles == 48);
        apart += c.tiles_apart;
    }
    CHECK(apart <= 2);
}

TEST_CASE("compare_noisy_renders: a bias of three standard errors per pixel shows in its tiles",
          "[grader]") {
    // Per tile the mean of 64 pixels has spread 0.2 / sqrt(12) / 8 = 0.0072; over 8 and 16
    // renders the difference's standard error is 0.0031, so a bias of 0.03 is near 10 of them.
    const NoisyComparison c = compare_noisy_renders(
        noisy_renders(5, 8, 0.03), noisy_renders(6, 16, 0.0), kTile, kBound, kFloor);
    CHECK(c.tiles_apart == 24);  // the left half's tiles, all of them
    CHECK(c.worst_i < kWidth / 2);
    CHECK(c.worst_z > kBound);
    CHECK(c.worst_student.z == Approx(0.13));
    CHECK(c.worst_reference.z == Approx(0.1));
}

TEST_CASE("compare_noisy_renders: noise added to a biased render does not widen its bound",
          "[grader]") {
    // Ten times the reference's noise would make the bias of 0.03 one standard error: every tile
    // of the image is apart for spreading beyond kSpreadRatioBound times the reference's.
    const NoisyComparison c = compare_noisy_renders(
        noisy_renders(5, 8, 0.03, 2.0), noisy_renders(6, 16, 0.0), kTile, kBound, kFloor);
    CHECK(c.tiles_apart == 48);
    // Half as much noise again as the reference's, unbiased (a sampler a little worse than the
    // reference's): over 20 comparisons, fewer tiles apart than the 1% a render check allows.
    int apart = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        apart += compare_noisy_renders(noisy_renders(seed, 8, 0.0, 0.3),
                                       noisy_renders(1000 + seed, 16, 0.0), kTile, kBound, kFloor)
                     .tiles_apart;
    }
    CHECK(apart < 0.01 * 20 * 48);
}

TEST_CASE("compare_noisy_renders: noise-free tiles agree within the floor, a NaN is apart",
          "[grader]") {
    std::vector<Image> flat(4, Image(kWidth, kHeight));
    std::vector<Image> rounded = flat;
    rounded[1].set(3, 3, Color(1e-7, 0, 0));
    CHECK(compare_noisy_renders(rounded, flat, kTile, kBound, kFloor).tiles_apart == 0);
    std::vector<Image> nan = flat;
    nan[0].set(20, 30, Color(std::numeric_limits<double>::quiet_NaN(), 0, 0));
    const NoisyComparison c = compare_noisy_renders(nan, flat, kTile, kBound, kFloor);
    CHECK(c.tiles_apart == 1);
    CHECK(c.worst_i == 16);
    CHECK(c.worst_j == 24);
}

TEST_CASE("compare_noisy_renders: renders of other sizes, or one render, are refused", "[grader]") {
    const std::vector<Image> two(2, Image(kWidth, kHeight));
    CHECK_THROWS_AS(compare_noisy_renders({Image(kWidth, kHeight), Image(kWidth, 47)}, two, kTile,
                                          kBound, kFloor),
                    std::invalid_argument);
    CHECK_THROWS_AS(compare_noisy_renders({Image(kWidth, kHeight)}, two, kTile, kBound, kFloor),
                    std::invalid_argument);
}

TEST_CASE("mean_image: the pixel by pixel mean", "[grader]") {
    std::vector<Image> renders(2, Image(2, 1));
    renders[0].set(1, 0, Color(1, 2, 3));
    renders[1].set(1, 0, Color(3, 2, 1));
    const Image mean = mean_image(renders);
    CHECK(mean.at(1, 0) == Color(2, 2, 2));
    CHECK(mean.at(0, 0) == Color(0, 0, 0));
}

TEST_CASE("tile_deviations: one pixel per tile, each tile's spread over the renders", "[grader]") {
    std::vector<Image> renders = {Image(20, 12), Image(20, 12)};
    for (int j = 0; j < 12; ++j) {
        for (int i = 0; i < 20; ++i)
            renders[1].set(i, j, Color(i < 8 ? 0.2 : 0.0));
    }
    const Image deviations = tile_deviations(renders, kTile);
    // 20 x 12 pixels in tiles of 8: 3 x 2 tiles, the last column and row smaller.
    REQUIRE(deviations.width() == 3);
    REQUIRE(deviations.height() == 2);
    // Tile means 0 and 0.2: a standard deviation of 0.2 / sqrt(2).
    CHECK(deviations.at(0, 1).r == Approx(0.2 / std::sqrt(2.0)));
    CHECK(deviations.at(1, 0).r == 0.0);
    CHECK_THROWS_AS(tile_deviations({renders[0]}, kTile), std::invalid_argument);
}

TEST_CASE("compare_render_with_spread: one render of the mean passes, a biased one fails there",
          "[grader]") {
    const std::vector<Image> reference = noisy_renders(500, 16, 0.0);
    const Image mean = mean_image(reference);
    const Image spread = tile_deviations(reference, kTile);
    int apart = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const NoisyComparison c = compare_render_with_spread(
            noisy_renders(seed, 1, 0.0).front(), mean, spread, 16, kTile, kBound, kFloor);
        CHECK(c.tiles == 48);
        apart += c.tiles_apart;
    }
    CHECK(apart <= 2);
    // A bias of 0.02 where x < 32: some 4.5 standard errors of a single render's tile.
    const NoisyComparison biased = compare_render_with_spread(
        noisy_renders(1, 1, 0.02).front(), mean, spread, 16, kTile, kBound, kFloor);
    CHECK(biased.tiles_apart >= 12);
    CHECK(biased.worst_i < kWidth / 2);
    CHECK_THROWS_AS(compare_render_with_spread(noisy_renders(1, 1, 0.0).front(), mean, mean, 16,
                                               kTile, kBound, kFloor),
                    std::invalid_argument);
}
