#pragma once

#include <random>

namespace raystep {

// The bench's random numbers come from std::mt19937_64, whose sequence the C++ standard fixes,
// through these functions rather than std::uniform_real_distribution, whose algorithm each
// standard library chooses: so a seed makes the same rays and scenes with every compiler.

/// A double uniform in [0, 1): the top 53 bits of one draw, scaled by 2^-53 (exact).
inline double uniform01(std::mt19937_64& random) {
    return static_cast<double>(random() >> 11) * 0x1p-53;
}

/// A double uniform in [low, high).
inline double uniform(std::mt19937_64& random, double low, double high) {
    return low + (high - low) * uniform01(random);
}

}  // namespace raystep
