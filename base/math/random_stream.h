#pragma once

// The random numbers of a render (stage 8's samples): one stream per pixel and sample pass, each
// number a function of (seed, stream, counter) alone, so that a pixel's samples are the same for
// any thread count, any tile order and on any platform. SplitMix64 (Steele, Lea and Flood,
// "Fast splittable pseudorandom number generators", 2014) is counter-based by construction: the
// n-th output is the finalizer applied to key + n times the golden gamma, so a stream needs no
// state but its key and its counter, and seeding one per pixel costs nothing.

#include <cstdint>

#include "base/math/types.h"

namespace raystep {

class RandomStream {
  public:
    /// Stream `stream` (a pixel and pass, say) of the render seeded with `seed`.
    RandomStream(std::uint64_t seed, std::uint64_t stream) : key_(mix(mix(seed) ^ stream)) {}

    /// Uniform in [0, 1): 53 random bits, so never 1.
    double next() { return static_cast<double>(bits() >> 11) * 0x1p-53; }

    /// Two numbers, x drawn first: a point uniform in [0, 1)^2.
    Vec2 next2() {
        const double x = next();
        return {x, next()};
    }

    /// How many numbers this stream has given.
    std::uint64_t count() const { return counter_; }

  private:
    static constexpr std::uint64_t kGoldenGamma = 0x9E3779B97F4A7C15ull;

    std::uint64_t bits() { return mix(key_ + ++counter_ * kGoldenGamma); }

    // SplitMix64's finalizer (the variant of Stafford's Mix13 it publishes).
    static std::uint64_t mix(std::uint64_t z) {
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }

    std::uint64_t key_;
    std::uint64_t counter_ = 0;
};

}  // namespace raystep
