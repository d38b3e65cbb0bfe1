#pragma once

#include <cstdint>
#include <vector>

#include "grader/grade/check_definition.h"

namespace raystep::grade {

// What stage 8's statistical checks share (stage8_statistics.cpp: the sample patterns;
// stage8_mean_statistics.cpp: the means of pixel_colour and quad_light_shading;
// stage8_film_light_statistics.cpp: a pixel's film and light samples together).

// Each statistical check's false-fail rate: at 1e-4, a right submission graded on 100 seeds
// keeps full marks on all four checks with probability 0.96 at worst; the mutants miss their
// means by tens or thousands of standard errors, so a smaller rate would cost them nothing.
inline constexpr double kCheckAlpha = 1e-4;

// The streams of a mean: 400 give a standard error of a twentieth of one stream's spread, and a
// mean over them near enough to normal for the z-test at the rates above (each estimate is
// itself a mean of 16 or more samples).
inline constexpr int kMeanStreams = 400;

// A spread below which a mean's standard error is not taken: a right regular-like estimator has
// none, and rounding alone gives one near 1e-16; 1e-9 keeps any bias above it visible.
inline constexpr double kDeviationFloor = 1e-9;

// Histograms of 10 x 10 bins with 80 points expected in each: Pearson's statistic is then close
// to its chi-square law (every bin expects far more than 5).
inline constexpr int kBins = 10;

// Where each case's streams start: cases of one check never share a stream.
class StreamCounter {
  public:
    /// The next `count` stream numbers.
    std::vector<std::uint64_t> next(int count) {
        std::vector<std::uint64_t> streams;
        for (int k = 0; k < count; ++k)
            streams.push_back(first_++);
        return streams;
    }

  private:
    std::uint64_t first_ = 0;
};

/// The cases of "stage8.statistics.jittered", drawn at statistics_seed() (stage8_statistics.cpp).
std::vector<ProbeCase> jittered_cases();

/// The cases of "stage8.statistics.pixel_colour" and "stage8.statistics.quad_light_shading",
/// drawn at statistics_seed() (stage8_mean_statistics.cpp).
std::vector<ProbeCase> pixel_cases();
std::vector<ProbeCase> shading_cases();

/// The cases of "stage8.statistics.film_and_light": film and light samples of one pixel drawn
/// from its one stream (stage8_film_light_statistics.cpp).
std::vector<ProbeCase> film_and_light_cases();

}  // namespace raystep::grade
