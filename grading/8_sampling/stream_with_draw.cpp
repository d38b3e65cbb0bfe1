#include "grading/8_sampling/stream_with_draw.h"

#include <cmath>

namespace raystep::grade {

namespace {

// RandomStream's arithmetic, as base/math/random_stream.h has it: the key mix(mix(seed) ^ stream),
// and the n-th number (from 1) mix(key + n gamma) >> 11 times 2^-53. The test
// (grading/8_sampling/tests/stream_with_draw_test.cpp) holds the two together.
constexpr std::uint64_t kGoldenGamma = 0x9E3779B97F4A7C15ull;
constexpr std::uint64_t kFirstFactor = 0xBF58476D1CE4E5B9ull;
constexpr std::uint64_t kSecondFactor = 0x94D049BB133111EBull;

std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * kFirstFactor;
    z = (z ^ (z >> 27)) * kSecondFactor;
    return z ^ (z >> 31);
}

// The inverse of z ^ (z >> shift): each pass restores `shift` more of the high bits.
std::uint64_t unshift(std::uint64_t z, int shift) {
    std::uint64_t x = z;
    for (int done = shift; done < 64; done += shift)
        x = z ^ (x >> shift);
    return x;
}

// The inverse of an odd factor modulo 2^64, by Newton's iteration: each step doubles the bits
// that are right, from the 3 that x = a has (a a = 1 mod 8 for odd a).
std::uint64_t inverse(std::uint64_t a) {
    std::uint64_t x = a;
    for (int step = 0; step < 5; ++step)
        x *= 2 - a * x;
    return x;
}

std::uint64_t unmix(std::uint64_t z) {
    z = unshift(z, 31) * inverse(kSecondFactor);
    z = unshift(z, 27) * inverse(kFirstFactor);
    return unshift(z, 30);
}

}  // namespace

std::uint64_t stream_with_draw(std::uint64_t seed, std::uint64_t draw, double value) {
    const auto bits = static_cast<std::uint64_t>(std::ldexp(value, 53)) << 11;
    const std::uint64_t key = unmix(bits) - (draw + 1) * kGoldenGamma;
    return unmix(key) ^ mix(seed);
}

}  // namespace raystep::grade
