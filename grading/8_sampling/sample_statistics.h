#pragma once

#include <vector>

#include "base/math/chi_square.h"
#include "base/math/types.h"

namespace raystep::grade {

// The statistics behind the grader's checks of random answers (stage 8's samples and means, the
// noisy renders): tests whose false-fail rate is stated in advance, so that a right answer drawn
// from other random numbers passes at that rate and a biased one fails. Each returns a p-value or
// takes the test's alpha; a check that runs m tests gives each alpha / m (Bonferroni), so that
// its own false-fail rate is at most alpha.

// The chi-square test's p-value is base/math/chi_square.h's chi_square_p_value.

/// z with P(|Z| > z) = alpha for a standard normal Z: the bound of a two-sided z-test.
/// alpha in (0, 1).
double two_sided_normal_bound(double alpha);

/// z with P(Z > z) = alpha: the bound of a one-sided test.
double one_sided_normal_bound(double alpha);

/// Pearson's statistic of `points` binned into a bins x bins histogram of [0, 1)^2 against the
/// uniform distribution (each bin expecting points.size() / bins^2). A point outside [0, 1)^2 or
/// NaN makes the statistic infinite. Degrees of freedom: bins^2 - 1.
double uniform_square_chi_square(const std::vector<Vec2>& points, int bins);

/// The mean of independent estimates and its standard error, the estimates' own standard
/// deviation over sqrt(n), that deviation no smaller than `deviation_floor` (a right estimator
/// with no spread, or a spread only rounding makes, is then judged against the floor).
struct MeanEstimate {
    double mean = 0.0;
    double standard_error = 0.0;
    double deviation = 0.0;  ///< the estimates' standard deviation, before the floor
};
MeanEstimate estimate_mean(const std::vector<double>& estimates, double deviation_floor);

/// The two-sided z-test of a mean against its exact value: |mean - exact| <= bound standard
/// errors. Written so that a NaN fails.
bool mean_consistent(const MeanEstimate& estimate, double exact, double bound);

/// The one-sided test that independent estimates' variance is not above `variance`: the sample
/// variance s^2 against it, in standard errors of s^2 estimated from the sample's fourth central
/// moment, sqrt((m4 - s^4) / n). True when s^2 - variance <= bound standard errors (or s^2 is at
/// most `variance`); false for NaN.
bool variance_not_above(const std::vector<double>& estimates, double variance, double bound);

}  // namespace raystep::grade
