#pragma once

#include <vector>

#include "base/image/image.h"

namespace raystep {

// The arithmetic of the sampling noise study: how far a render is from the converged one, the
// mean and spread over seeds, and the rate at which the error falls.

/// The root mean square difference of two images of the same size, over every pixel and
/// channel. Throws std::invalid_argument for images of different sizes or no pixels.
double image_rmse(const Image& image, const Image& reference);

/// A mean over runs and how far the runs scatter around it.
struct MeanSpread {
    double mean = 0.0;
    double spread = 0.0;  ///< the sample standard deviation; 0 for a single value
};

/// The mean and sample standard deviation (n - 1 in the denominator) of `values`. Throws
/// std::invalid_argument when there are none.
MeanSpread mean_and_spread(const std::vector<double>& values);

/// The slope of the least-squares line through (log x, log y): the exponent p of y ~ x^p, so
/// that an error falling as 1/sqrt(N) has slope -0.5. Throws std::invalid_argument for fewer than
/// two points, lists of different lengths, a value that is not positive, or x all equal.
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace raystep
