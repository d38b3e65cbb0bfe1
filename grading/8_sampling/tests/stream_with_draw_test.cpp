// The grader's streams chosen for what they draw (grading/8_sampling/stream_with_draw.h) against
// RandomStream itself: the chosen number at the chosen draw, for any seed.

#include <cstdint>

#include "base/math/random_stream.h"
#include "base/testing/catch.h"
#include "grading/8_sampling/stream_with_draw.h"

using namespace raystep;

TEST_CASE("stream_with_draw: RandomStream(seed, stream) draws the chosen number at the chosen draw",
          "[grader]") {
    for (const std::uint64_t seed : {0ull, 8ull, 12345678901ull}) {
        for (std::uint64_t draw = 0; draw < 40; ++draw) {
            for (const double value : {0.0, 0.5, 1.0 - 0x1p-53, 12345 * 0x1p-53}) {
                CAPTURE(seed, draw, value);
                RandomStream random(seed, grade::stream_with_draw(seed, draw, value));
                for (std::uint64_t k = 0; k < draw; ++k)
                    random.next();
                CHECK(random.next() == value);
            }
        }
    }
}

TEST_CASE("stream_with_draw: the public tests' stream that starts at 1 - 2^-53", "[grader]") {
    // stages/8_sampling/tests/samples_test.cpp, kStreamStartingBelowOne, found the same way.
    CHECK(grade::stream_with_draw(0, 0, 1.0 - 0x1p-53) == 0xad3729fa17bb46b2ull);
}
