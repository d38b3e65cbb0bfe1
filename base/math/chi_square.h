#pragma once

#include <vector>

namespace raystep {

/// P(X >= statistic) for X chi-square with `degrees` degrees of freedom: the p-value of a
/// chi-square test, the regularized upper incomplete gamma function Q(degrees / 2, statistic / 2),
/// by its series below a + 1 and its continued fraction above (Press et al., Numerical Recipes,
/// 3rd ed., 6.2), each to double precision. 1 for a statistic <= 0; 0 for infinity and NaN, so
/// that they fail. Throws std::domain_error for fewer than 1 degree. A test of samples against
/// their density fails where this is below its significance: a right sampler fails it with
/// exactly that probability. The grader's statistical checks (grading/8_sampling) and the
/// samplers' public tests (stages 8 and 10) both take their verdict from it.
double chi_square_p_value(double statistic, int degrees);

/// Pearson's statistic of `observed` counts against `expected` ones, bin by bin, and its degrees
/// of freedom: bins expecting fewer than 5 are pooled into one, as Nori's warptest does, so that
/// the statistic keeps close to its chi-square law. The statistic is infinite where counts fell
/// in bins that together expect none. The two lists are of one length.
struct PooledChiSquare {
    double statistic = 0.0;
    int degrees = 1;
};
PooledChiSquare pooled_chi_square(const std::vector<double>& observed,
                                  const std::vector<double>& expected);

}  // namespace raystep
