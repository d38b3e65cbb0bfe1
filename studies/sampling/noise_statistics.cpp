#include "studies/sampling/noise_statistics.h"

#include <cmath>
#include <stdexcept>

namespace raystep {

double image_rmse(const Image& image, const Image& reference) {
    if (image.width() != reference.width() || image.height() != reference.height()) {
        throw std::invalid_argument("image_rmse: the images differ in size");
    }
    if (image.width() == 0 || image.height() == 0) {
        throw std::invalid_argument("image_rmse: the images have no pixels");
    }
    double sum = 0.0;
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            const Color d = image.at(i, j) - reference.at(i, j);
            sum += d.r * d.r + d.g * d.g + d.b * d.b;
        }
    }
    return std::sqrt(sum / (3.0 * image.width() * image.height()));
}

MeanSpread mean_and_spread(const std::vector<double>& values) {
    if (values.empty()) throw std::invalid_argument("mean_and_spread: no values");
    double sum = 0.0;
    for (const double v : values)
        sum += v;
    MeanSpread result;
    result.mean = sum / static_cast<double>(values.size());
    if (values.size() < 2) return result;
    double squares = 0.0;
    for (const double v : values)
        squares += (v - result.mean) * (v - result.mean);
    result.spread = std::sqrt(squares / static_cast<double>(values.size() - 1));
    return result;
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size() || x.size() < 2) {
        throw std::invalid_argument("log_log_slope: needs two or more (x, y) pairs");
    }
    // Least squares on (log x, log y); !(v > 0) also rejects NaN
    double mean_x = 0.0;
    double mean_y = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k) {
        if (!(x[k] > 0.0) || !(y[k] > 0.0)) {
            throw std::invalid_argument("log_log_slope: a value is not positive");
        }
        mean_x += std::log(x[k]);
        mean_y += std::log(y[k]);
    }
    const double n = static_cast<double>(x.size());
    mean_x /= n;
    mean_y /= n;
    double sxy = 0.0;
    double sxx = 0.0;
    for (std::size_t k = 0; k < x.size(); ++k) {
        const double dx = std::log(x[k]) - mean_x;
        sxy += dx * (std::log(y[k]) - mean_y);
        sxx += dx * dx;
    }
    if (sxx == 0.0) throw std::invalid_argument("log_log_slope: every x is the same");
    return sxy / sxx;
}

}  // namespace raystep
