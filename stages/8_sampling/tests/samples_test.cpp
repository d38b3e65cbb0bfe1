// Public tests for stage 8, sample patterns over the unit square. Run them with
// `ctest --preset student -L stage8`, one function's with
// `build/student/bin/raystep_stage8_tests "jittered_samples:*"`.
//
// Your samples need not be the reference's: you may draw the numbers in another order. So the
// tests ask what any right pattern does: how many points, in which strata, and spread how. The
// spread is a chi-square test over many streams of a fixed seed, with a threshold that a right
// implementation exceeds with probability below 1e-6; the seed is fixed, so the test gives the
// same answer on every run. Each test calls your function before its CHECKs: a stub is
// reported once. A loop over streams or points stops at the first that fails.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/testing/catch.h"
#include "base/testing/uses.h"
#include "stages/8_sampling/sampling.h"

using namespace raystep;
using raystep::testing::uses;

namespace {

constexpr std::uint64_t kSeed = 2026;

// RandomStream(0, this)'s first number is 1 - 2^-53, the largest next() gives: found by running
// SplitMix64's finalizer backwards (each of its steps is invertible) from the bits 2^53 - 1.
constexpr std::uint64_t kStreamStartingBelowOne = 0xad3729fa17bb46b2;

std::string text(const Vec2& p) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "(%.17g, %.17g)", p.x, p.y);
    return buffer;
}

// The stratum column (or row) of a coordinate in an n x n grid: the number of boundaries k / n,
// k = 1 .. n - 1, at or below it, each boundary computed as the stubs' formula computes it.
int stratum_of(double x, int n) {
    int stratum = 0;
    for (int k = 1; k < n; ++k)
        stratum += x >= static_cast<double>(k) / n ? 1 : 0;
    return stratum;
}

// Pearson's chi-square of counts against the same expected count in every bin.
double chi_square(const std::vector<int>& counts, double expected) {
    double sum = 0.0;
    for (int count : counts)
        sum += (count - expected) * (count - expected) / expected;
    return sum;
}

// The chi-square quantiles that a right implementation exceeds with probability 1e-6: 56.49 for
// 15 degrees of freedom (16 bins), 131.37 for 63 (64 bins). Upper tail of the chi-square
// distribution, Q(k/2, x/2), solved for 1e-6; each bin expects 1000 points, far above the 5
// the chi-square approximation asks for.
constexpr double kChiSquare15 = 56.49;
constexpr double kChiSquare63 = 131.37;

bool in_unit_square(const Vec2& p) {
    return p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0;  // false for NaN
}

}  // namespace

TEST_CASE("jittered_samples: n x n points, exactly one in each stratum, all in the unit square",
          "[stage8]") {
    for (int n : {1, 2, 3, 4, 7}) {
        for (std::uint64_t stream = 0; stream < 50; ++stream) {
            CAPTURE(n, stream);
            RandomStream random(kSeed, stream);
            const std::vector<Vec2> points = jittered_samples(n, random);
            REQUIRE(points.size() == static_cast<std::size_t>(n * n));
            std::vector<int> per_stratum(static_cast<std::size_t>(n * n), 0);
            for (const Vec2& p : points) {
                INFO("point " << text(p));
                REQUIRE(in_unit_square(p));
                ++per_stratum[static_cast<std::size_t>(stratum_of(p.y, n) * n +
                                                       stratum_of(p.x, n))];
            }
            for (int s = 0; s < n * n; ++s) {
                INFO("stratum column " << s % n << ", row " << s / n);
                REQUIRE(per_stratum[static_cast<std::size_t>(s)] == 1);
            }
        }
    }
}

TEST_CASE("jittered_samples: a u of 1 - 2^-53, the largest a stream gives, stays in its stratum",
          "[stage8]") {
    INFO(
        "The first number of this stream is 1 - 2^-53. In doubles a + u rounds up to a + 1 (1 + "
        "(1 - 2^-53) is a tie, and ties go to the even 2), so (a + u) / n lands on the next "
        "stratum's edge, or on 1, outside the square. Whichever stratum and coordinate it goes "
        "to, with n = 2 or 3, the point must stay below its stratum's far edge.");
    for (int n : {2, 3}) {
        CAPTURE(n);
        RandomStream random(0, kStreamStartingBelowOne);
        const std::vector<Vec2> points = jittered_samples(n, random);
        REQUIRE(RandomStream(0, kStreamStartingBelowOne).next() == 1.0 - 0x1p-53);
        REQUIRE(points.size() == static_cast<std::size_t>(n * n));
        std::vector<int> per_stratum(static_cast<std::size_t>(n * n), 0);
        for (const Vec2& p : points) {
            INFO("point " << text(p));
            REQUIRE(in_unit_square(p));
            ++per_stratum[static_cast<std::size_t>(stratum_of(p.y, n) * n + stratum_of(p.x, n))];
        }
        REQUIRE(per_stratum == std::vector<int>(static_cast<std::size_t>(n * n), 1));
    }
}

TEST_CASE("jittered_samples: each point is uniform inside its stratum (chi-square, 16 bins)",
          "[stage8]") {
    INFO(
        "1000 streams of 4 x 4 samples: each point's place inside its own stratum, (4x - a, "
        "4y - b), falls in one of 4 x 4 bins; a right implementation puts about 1000 in each. A "
        "point always at the stratum's centre, or u drawn once for all strata, fails.");
    const int n = 4;
    std::vector<int> bins(16, 0);
    for (std::uint64_t stream = 0; stream < 1000; ++stream) {
        RandomStream random(kSeed, stream);
        for (const Vec2& p : jittered_samples(n, random)) {
            // 4 x is exact in binary: the place inside the stratum has no rounding.
            const double fx = n * p.x - std::floor(n * p.x);
            const double fy = n * p.y - std::floor(n * p.y);
            const int bx = std::clamp(static_cast<int>(fx * 4), 0, 3);
            const int by = std::clamp(static_cast<int>(fy * 4), 0, 3);
            ++bins[static_cast<std::size_t>(by * 4 + bx)];
        }
    }
    const double statistic = chi_square(bins, 1000.0);
    CAPTURE(statistic, kChiSquare15);
    CHECK(statistic < kChiSquare15);
}

TEST_CASE("jittered_samples: each call draws new points", "[stage8]") {
    INFO("Two calls on the same stream give two different sets: the stream moves on.");
    RandomStream random(kSeed, 0);
    const std::vector<Vec2> first = jittered_samples(2, random);
    const std::vector<Vec2> second = jittered_samples(2, random);
    CHECK(first != second);
}

TEST_CASE("jittered_samples: fewer than 1 stratum per side throws std::domain_error", "[stage8]") {
    RandomStream random(kSeed, 0);
    const std::vector<Vec2> one = jittered_samples(1, random);
    CHECK(one.size() == 1);
    CHECK_THROWS_AS(jittered_samples(0, random), std::domain_error);
    CHECK_THROWS_AS(jittered_samples(-3, random), std::domain_error);
}

TEST_CASE("regular_samples: the centres of the n x n strata, exactly", "[stage8]") {
    INFO("n = 4: every coordinate is one of 1/8, 3/8, 5/8, 7/8, each pair once; any order.");
    std::vector<Vec2> points = regular_samples(4);
    REQUIRE(points.size() == 16);
    std::vector<Vec2> expected;
    for (double y : {0.125, 0.375, 0.625, 0.875}) {
        for (double x : {0.125, 0.375, 0.625, 0.875})
            expected.push_back({x, y});
    }
    const auto by_y_then_x = [](const Vec2& a, const Vec2& b) {
        return a.y < b.y || (a.y == b.y && a.x < b.x);
    };
    std::sort(points.begin(), points.end(), by_y_then_x);
    for (std::size_t k = 0; k < points.size(); ++k) {
        INFO("sorted point " << k << ": " << text(points[k]) << ", expected " << text(expected[k]));
        REQUIRE(points[k] == expected[k]);
    }
    const std::vector<Vec2> centre = regular_samples(1);
    REQUIRE(centre.size() == 1);
    CHECK(centre[0] == Vec2(0.5, 0.5));
    CHECK_THROWS_AS(regular_samples(0), std::domain_error);
}

TEST_CASE("random_samples: count points, uniform over the unit square (chi-square, 64 bins)",
          "[stage8]") {
    INFO(
        "1000 streams of 64 points, binned into 8 x 8 cells of the square: about 1000 in each. "
        "Points all in one corner, or x = y, fail.");
    std::vector<int> bins(64, 0);
    for (std::uint64_t stream = 0; stream < 1000; ++stream) {
        RandomStream random(kSeed, stream);
        const std::vector<Vec2> points = random_samples(64, random);
        REQUIRE(points.size() == 64);
        for (const Vec2& p : points) {
            INFO("stream " << stream << ", point " << text(p));
            REQUIRE(in_unit_square(p));
            // 8 x is exact in binary, and below 8 for x < 1.
            ++bins[static_cast<std::size_t>(static_cast<int>(8 * p.y) * 8 +
                                            static_cast<int>(8 * p.x))];
        }
    }
    const double statistic = chi_square(bins, 1000.0);
    CAPTURE(statistic, kChiSquare63);
    CHECK(statistic < kChiSquare63);
}

TEST_CASE("random_samples: fewer than 1 point throws std::domain_error", "[stage8]") {
    RandomStream random(kSeed, 0);
    const std::vector<Vec2> three = random_samples(3, random);
    CHECK(three.size() == 3);
    CHECK_THROWS_AS(random_samples(0, random), std::domain_error);
}

TEST_CASE("samples: jittered and regular take n^2 samples as n x n strata", "[stage8]") {
    INFO(uses("samples", "jittered_samples, regular_samples and random_samples"));
    RandomStream random(kSeed, 0);
    const std::vector<Vec2> jittered = samples(SamplePattern::jittered, 9, random);
    REQUIRE(jittered.size() == 9);
    std::vector<int> per_stratum(9, 0);
    for (const Vec2& p : jittered)
        ++per_stratum[static_cast<std::size_t>(stratum_of(p.y, 3) * 3 + stratum_of(p.x, 3))];
    CHECK(per_stratum == std::vector<int>(9, 1));

    std::vector<Vec2> regular = samples(SamplePattern::regular, 4, random);
    std::sort(regular.begin(), regular.end(),
              [](const Vec2& a, const Vec2& b) { return a.y < b.y || (a.y == b.y && a.x < b.x); });
    const std::vector<Vec2> centres{{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}};
    REQUIRE(regular.size() == 4);
    for (std::size_t k = 0; k < regular.size(); ++k) {
        INFO("sorted point " << k << ": " << text(regular[k]) << ", expected " << text(centres[k]));
        REQUIRE(regular[k] == centres[k]);
    }
}

TEST_CASE("samples: random takes any count", "[stage8]") {
    INFO(uses("samples", "jittered_samples, regular_samples and random_samples"));
    RandomStream random(kSeed, 0);
    const std::vector<Vec2> points = samples(SamplePattern::random, 5, random);
    REQUIRE(points.size() == 5);
    for (const Vec2& p : points) {
        INFO("point " << text(p));
        REQUIRE(in_unit_square(p));
    }
}

TEST_CASE("samples: jittered or regular with a count that is not a square throws", "[stage8]") {
    INFO(uses("samples", "jittered_samples, regular_samples and random_samples"));
    INFO("n x n strata need count = n^2: 2, 8 and 10 have no n; std::domain_error, not n = 1.");
    RandomStream random(kSeed, 0);
    const std::vector<Vec2> sixteen = samples(SamplePattern::jittered, 16, random);
    CHECK(sixteen.size() == 16);
    for (int count : {2, 8, 10}) {
        CAPTURE(count);
        REQUIRE_THROWS_AS(samples(SamplePattern::jittered, count, random), std::domain_error);
        REQUIRE_THROWS_AS(samples(SamplePattern::regular, count, random), std::domain_error);
    }
}
