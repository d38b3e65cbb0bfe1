#include "base/math/portable_random.h"

#include <glm/geometric.hpp>

#include "base/testing/catch.h"

using namespace raystep;

TEST_CASE("PortableRandom: a seed and an index give the same numbers on every platform",
          "[random]") {
    // mt19937_64's sequence is fixed by the standard and the distributions use only its bits, so
    // these values are what libstdc++, libc++ and MSVC's library all produce.
    CHECK(PortableRandom(1).unit() == 0.65538580929711543);
    CHECK(PortableRandom(1, 1).unit() == 0.60749427783545162);
}

TEST_CASE("PortableRandom: draws stay inside their ranges", "[random]") {
    PortableRandom random(7);
    for (int k = 0; k < 1000; ++k) {
        CAPTURE(k);
        const double u = random.uniform(-2.0, 3.0);
        REQUIRE(u >= -2.0);
        REQUIRE(u < 3.0);
        const std::int64_t n = random.integer(-3, 4);
        REQUIRE(n >= -3);
        REQUIRE(n <= 4);
        REQUIRE(glm::length(random.unit_vector()) == Approx(1.0).epsilon(1e-15));
    }
}
