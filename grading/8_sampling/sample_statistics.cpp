#include "grading/8_sampling/sample_statistics.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace raystep::grade {

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

double normal_upper_tail(double z) {
    return 0.5 * std::erfc(z / std::sqrt(2.0));
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

double one_sided_normal_bound(double alpha) {
    if (!(alpha > 0.0 && alpha < 1.0)) {
        throw std::domain_error("one_sided_normal_bound: alpha outside (0, 1)");
    }
    // Bisection on the upper tail, which falls from 1 to 0: 200 halvings of [-40, 40] reach the
    // spacing of doubles.
    double low = -40.0;
    double high = 40.0;
    for (int step = 0; step < 200; ++step) {
        const double middle = 0.5 * (low + high);
        (normal_upper_tail(middle) > alpha ? low : high) = middle;
    }
    return 0.5 * (low + high);
}

double two_sided_normal_bound(double alpha) {
    return one_sided_normal_bound(0.5 * alpha);
}

double uniform_square_chi_square(const std::vector<Vec2>& points, int bins) {
    if (points.empty() || bins < 1) throw std::domain_error("uniform_square_chi_square: no data");
    std::vector<double> counts(static_cast<std::size_t>(bins) * bins, 0.0);
    for (const Vec2& p : points) {
        // Written so that NaN lands here too.
        if (!(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0)) {
            return std::numeric_limits<double>::infinity();
        }
        const int a = std::min(static_cast<int>(p.x * bins), bins - 1);
        const int b = std::min(static_cast<int>(p.y * bins), bins - 1);
        counts[static_cast<std::size_t>(b) * bins + a] += 1.0;
    }
    const double expected = static_cast<double>(points.size()) / counts.size();
    double statistic = 0.0;
    for (double count : counts)
        statistic += (count - expected) * (count - expected) / expected;
    return statistic;
}

MeanEstimate estimate_mean(const std::vector<double>& estimates, double deviation_floor) {
    if (estimates.size() < 2) throw std::domain_error("estimate_mean: fewer than two estimates");
    const double n = static_cast<double>(estimates.size());
    double sum = 0.0;
    for (double e : estimates)
        sum += e;
    const double mean = sum / n;
    double squares = 0.0;
    for (double e : estimates)
        squares += (e - mean) * (e - mean);
    const double deviation = std::sqrt(squares / (n - 1.0));
    return {mean, std::max(deviation, deviation_floor) / std::sqrt(n), deviation};
}

bool mean_consistent(const MeanEstimate& estimate, double exact, double bound) {
    return std::abs(estimate.mean - exact) <= bound * estimate.standard_error;
}

bool variance_not_above(const std::vector<double>& estimates, double variance, double bound) {
    if (estimates.size() < 2) throw std::domain_error("variance_not_above: too few estimates");
    const double n = static_cast<double>(estimates.size());
    double sum = 0.0;
    for (double e : estimates)
        sum += e;
    const double mean = sum / n;
    double m2 = 0.0;
    double m4 = 0.0;
    for (double e : estimates) {
        const double d2 = (e - mean) * (e - mean);
        m2 += d2;
        m4 += d2 * d2;
    }
    const double s2 = m2 / (n - 1.0);
    const double fourth = m4 / n;
    if (s2 <= variance) return true;
    const double error = std::sqrt(std::max(fourth - s2 * s2, 0.0) / n);
    return s2 - variance <= bound * error;
}

}  // namespace raystep::grade
