#include "base/math/chi_square.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace raystep {

namespace {

// Relative accuracy at which the series and the continued fraction stop: far below any alpha a
// check uses (1e-6 and up).
constexpr double kGammaAccuracy = 1e-15;
constexpr int kGammaTerms = 100000;

// P(a, x) by its series, for x < a + 1.
double lower_gamma_by_series(double a, double x) {
    double term = 1.0 / a;
    double sum = term;
    for (int n = 1; n < kGammaTerms; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::abs(term) < std::abs(sum) * kGammaAccuracy) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x) by its continued fraction, for x >= a + 1 (modified Lentz).
double upper_gamma_by_fraction(double a, double x) {
    constexpr double tiny = 1e-300;
    double b = x + 1.0 - a;
    double c = 1.0 / tiny;
    double d = 1.0 / b;
    double h = d;
    for (int n = 1; n < kGammaTerms; ++n) {
        const double an = -n * (n - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < kGammaAccuracy) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double chi_square_p_value(double statistic, int degrees) {
    if (degrees < 1) throw std::domain_error("chi_square_p_value: no degrees of freedom");
    if (std::isnan(statistic)) return 0.0;
    if (statistic <= 0.0) return 1.0;
    if (std::isinf(statistic)) return 0.0;
    const double a = 0.5 * degrees;
    const double x = 0.5 * statistic;
    return x < a + 1.0 ? 1.0 - lower_gamma_by_series(a, x) : upper_gamma_by_fraction(a, x);
}

PooledChiSquare pooled_chi_square(const std::vector<double>& observed,
                                  const std::vector<double>& expected) {
    PooledChiSquare result;
    double pooled_observed = 0.0;
    double pooled_expected = 0.0;
    int cells = 0;
    for (std::size_t k = 0; k < observed.size(); ++k) {
        if (expected[k] < 5.0) {
            pooled_observed += observed[k];
            pooled_expected += expected[k];
            continue;
        }
        result.statistic += (observed[k] - expected[k]) * (observed[k] - expected[k]) / expected[k];
        ++cells;
    }
    if (pooled_expected > 0.0) {
        result.statistic += (pooled_observed - pooled_expected) *
                            (pooled_observed - pooled_expected) / pooled_expected;
        ++cells;
    } else if (pooled_observed > 0.0) {
        result.statistic = std::numeric_limits<double>::infinity();
    }
    result.degrees = std::max(1, cells - 1);
    return result;
}

}  // namespace raystep
