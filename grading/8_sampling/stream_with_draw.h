#pragma once

#include <cstdint>

namespace raystep::grade {

// Streams chosen for what they draw: RandomStream (base/math/random_stream.h) is SplitMix64, whose
// every step is invertible, so for any seed there is a stream whose n-th number is any value
// next() can give. The grader hands such streams to the probe to ask what a student's code does
// with the extremes, 0 and 1 - 2^-53, at whichever draw it puts them, without a stream of its own
// that the student's code could tell apart.

/// The stream number whose `draw`-th number (from 0) of RandomStream(seed, stream).next() is
/// `value`, which must be k 2^-53 for an integer k in [0, 2^53).
std::uint64_t stream_with_draw(std::uint64_t seed, std::uint64_t draw, double value);

}  // namespace raystep::grade
