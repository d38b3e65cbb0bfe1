#pragma once

// The one random generator of everything the grader and the bench generate, the same on every
// platform: std::mt19937_64's output is fixed by the C++ standard, but
// std::uniform_real_distribution's is not (libstdc++ and libc++ differ), so the distributions are
// written here from its bits and a seed printed in a counterexample rebuilds the case anywhere.
// Every case has its own generator, seeded from its family's seed and the case's index, so that
// any one case can be rebuilt alone; a bench draws one stream from (seed, 0).

#include <cmath>
#include <cstdint>
#include <random>

#include "base/math/types.h"

namespace raystep {

class PortableRandom {
  public:
    /// The generator of case `index` of a family seeded with `seed`.
    PortableRandom(std::uint64_t seed, std::uint64_t index = 0) : engine_(mix(seed, index)) {}

    /// Uniform in [0, 1), 53 random bits.
    double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }

    /// Uniform in [low, high).
    double uniform(double low, double high) { return low + (high - low) * unit(); }

    /// Uniform in [low, high], whole numbers.
    std::int64_t integer(std::int64_t low, std::int64_t high) {
        const auto span = static_cast<std::uint64_t>(high - low) + 1;
        return low + static_cast<std::int64_t>(engine_() % span);
    }

    /// 10^e with e uniform in [low, high): magnitudes spread evenly over the decades.
    double decade(double low, double high) { return std::pow(10.0, uniform(low, high)); }

    /// A direction uniform on the unit sphere.
    Vec3 unit_vector() {
        const double z = uniform(-1.0, 1.0);
        const double angle = uniform(0.0, 2.0 * 3.14159265358979323846);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return {r * std::cos(angle), r * std::sin(angle), z};
    }

    /// A point uniform in the cube [-extent, extent]^3.
    Vec3 point(double extent) {
        return {uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)};
    }

  private:
    // SplitMix64's finalizer: nearby (seed, index) pairs give unrelated streams.
    static std::uint64_t mix(std::uint64_t seed, std::uint64_t index) {
        std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + index + 0x632BE59BD9B4E019ull;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }

    std::mt19937_64 engine_;
};

}  // namespace raystep
