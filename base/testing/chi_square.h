#pragma once

#include <cmath>
#include <limits>

namespace raystep::testing {

// The chi-square test's p-value: the probability that a chi-square variable of `degrees`
// degrees of freedom exceeds `statistic`, Q(k/2, x/2), the regularized upper incomplete gamma
// function. Computed by its power series below a + 1 and by Lentz's continued fraction above
// (the split of Numerical Recipes, section 6.2), each to double precision. A test of samples
// against their density fails where this is below its significance: a right sampler fails it
// with exactly that probability.
inline double chi_square_p_value(double statistic, int degrees) {
    const double a = 0.5 * degrees;
    const double x = 0.5 * statistic;
    if (!(x > 0.0)) return 1.0;
    const double log_prefix = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1.0) {
        // P(a, x) = x^a e^-x / Gamma(a) sum x^n / (a (a + 1) ... (a + n)); Q = 1 - P.
        double term = 1.0 / a;
        double sum = term;
        for (int n = 1; n < 10000 && std::abs(term) > 1e-17 * std::abs(sum); ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return 1.0 - sum * std::exp(log_prefix);
    }
    // Q(a, x) = x^a e^-x / Gamma(a) / (x + 1 - a - 1 (1 - a) / (x + 3 - a - ...)).
    constexpr double kTiny =
        std::numeric_limits<double>::min() / std::numeric_limits<double>::epsilon();
    double b = x + 1.0 - a;
    double c = 1.0 / kTiny;
    double d = 1.0 / b;
    double fraction = d;
    for (int n = 1; n < 10000; ++n) {
        const double an = -n * (n - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double step = d * c;
        fraction *= step;
        if (std::abs(step - 1.0) < 1e-16) break;
    }
    return std::exp(log_prefix) * fraction;
}

}  // namespace raystep::testing
