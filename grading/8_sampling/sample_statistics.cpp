#include "grading/8_sampling/sample_statistics.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace raystep::grade {

namespace {

double normal_upper_tail(double z) {
    return 0.5 * std::erfc(z / std::sqrt(2.0));
}

}  // namespace

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
