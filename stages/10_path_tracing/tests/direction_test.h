#pragma once

// Nori's warp test for a sampler of directions: the sphere cut into bins of equal solid angle,
// rows of z = cos(theta) by columns of phi (dw = dz dphi), the samples counted in each against
// the count the density predicts there (integrated over the bin on a finer grid), and Pearson's
// chi-square of the two. Bins that expect fewer than 5 are pooled into one, as the chi-square
// approximation asks. A right sampler fails with probability kSignificance; the seed is fixed,
// so a test gives the same answer on every run.

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "base/math/chi_square.h"
#include "base/math/random_stream.h"
#include "base/math/types.h"

namespace raystep::testing {

constexpr double kSignificance = 1e-6;

struct DirectionTestResult {
    double p_value = 0;
    std::string problem;  ///< a sample that is not a unit direction, or empty
};

inline Vec3 direction_at(double z, double phi) {
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// The chi-square p-value of `count` directions from `sample` (each given u from one stream of
/// `seed`) against `density` over the sphere.
inline DirectionTestResult direction_chi_square(const std::function<Vec3(const Vec2&)>& sample,
                                                const std::function<double(const Vec3&)>& density,
                                                std::uint64_t seed, int count = 200000,
                                                int rows = 40, int columns = 80) {
    const double two_pi = 2.0 * glm::pi<double>();
    std::vector<double> observed(static_cast<std::size_t>(rows * columns), 0.0);
    RandomStream random(seed, 0);
    DirectionTestResult result;
    for (int k = 0; k < count; ++k) {
        const Vec2 u = random.next2();
        const Vec3 d = sample(u);
        const double size = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (!(std::abs(size - 1.0) < 1e-9)) {
            std::ostringstream text;
            text.precision(17);
            text << "u = (" << u.x << ", " << u.y << ") gave (" << d.x << ", " << d.y << ", " << d.z
                 << "), of length " << size << ", not a unit direction";
            result.problem = text.str();
            return result;
        }
        const int row = std::clamp(static_cast<int>((d.z + 1.0) / 2.0 * rows), 0, rows - 1);
        double phi = std::atan2(d.y, d.x);
        if (phi < 0.0) phi += two_pi;
        const int column = std::clamp(static_cast<int>(phi / two_pi * columns), 0, columns - 1);
        observed[static_cast<std::size_t>(row * columns + column)] += 1.0;
    }
    // Each bin's expected count: the density at an 8 x 8 grid of midpoints, times their area.
    constexpr int kFine = 8;
    const double dz = 2.0 / rows / kFine;
    const double dphi = two_pi / columns / kFine;
    std::vector<double> expected(observed.size(), 0.0);
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            double sum = 0.0;
            for (int a = 0; a < kFine; ++a) {
                for (int b = 0; b < kFine; ++b) {
                    const double z = -1.0 + (row * kFine + a + 0.5) * dz;
                    const double phi = (column * kFine + b + 0.5) * dphi;
                    sum += density(direction_at(z, phi));
                }
            }
            expected[static_cast<std::size_t>(row * columns + column)] = sum * dz * dphi * count;
        }
    }
    const PooledChiSquare pooled = pooled_chi_square(observed, expected);
    if (std::isinf(pooled.statistic)) {
        result.problem = "samples fell where the density is 0";
        return result;
    }
    result.p_value = chi_square_p_value(pooled.statistic, pooled.degrees);
    return result;
}

/// The integral of `density` over the sphere, by the midpoint rule on a rows x columns grid.
inline double sphere_integral(const std::function<double(const Vec3&)>& density, int rows = 2000,
                              int columns = 400) {
    const double two_pi = 2.0 * glm::pi<double>();
    const double dz = 2.0 / rows;
    const double dphi = two_pi / columns;
    double sum = 0.0;
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column)
            sum += density(direction_at(-1.0 + (row + 0.5) * dz, (column + 0.5) * dphi));
    }
    return sum * dz * dphi;
}

}  // namespace raystep::testing
