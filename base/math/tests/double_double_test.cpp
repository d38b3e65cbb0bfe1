#include "base/math/double_double.h"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "base/math/double_double_vec.h"
#include "base/math/portable_random.h"
#include "base/testing/catch.h"

using namespace raystep;

namespace {

constexpr double kInf = HUGE_VAL;
constexpr double kU = 0x1p-53;  // the unit roundoff; a double-double's is about kU^2

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same_bits(const DoubleDouble& a, const DoubleDouble& b) {
    return same_bits(a.hi, b.hi) && same_bits(a.lo, b.lo);
}

// A whole number below 2^bits in magnitude, a double exactly (rounded to one when it has more than
// 53 bits): its sums and products with others like it are checked in 64-bit integers.
double whole(PortableRandom& random, int bits) {
    const double magnitude = std::ldexp(random.unit(), bits);
    const double x = std::nearbyint(magnitude);
    return random.integer(0, 1) ? x : -x;
}

std::int64_t integer(double x) {
    return static_cast<std::int64_t>(x);
}

// Dekker 1971's product without an fma: each factor split into halves of 26 bits (Veltkamp's
// split by 2^27 + 1), whose products are exact. An independent way to the same exact error.
DoubleDouble dekker_product(double a, double b) {
    const auto split = [](double x) {
        const double c = 134217729.0 * x;  // 2^27 + 1
        const double high = c - (c - x);
        return DoubleDouble(high, x - high);
    };
    const DoubleDouble sa = split(a);
    const DoubleDouble sb = split(b);
    const double p = a * b;
    // Shewchuk 1997's order of the partial products, each step exact
    const double e = sa.lo * sb.lo - (((p - sa.hi * sb.hi) - sa.lo * sb.hi) - sa.hi * sb.lo);
    return {p, e};
}

// Normalized: hi is hi + lo rounded to nearest. A zero hi has no exponent (ilogb(0) is INT_MIN).
bool normalized(const DoubleDouble& x) {
    if (x.hi == 0) return x.lo == 0;
    return x.hi + x.lo == x.hi && std::abs(x.lo) <= 0.5 * std::ldexp(1.0, std::ilogb(x.hi) - 52);
}

}  // namespace

TEST_CASE("two_sum: the error of a sum is exact, checked in integers at every scale", "[math]") {
    PortableRandom random(11);
    for (int k = 0; k < 20000; ++k) {
        CAPTURE(k);
        const double a = whole(random, static_cast<int>(random.integer(0, 61)));
        // Every other case cancels: b is -a give or take a little
        const double b = k % 2 ? whole(random, static_cast<int>(random.integer(0, 61)))
                               : -a + whole(random, static_cast<int>(random.integer(0, 12)));
        const DoubleDouble s = two_sum(a, b);
        REQUIRE(s.hi == a + b);
        REQUIRE(integer(s.hi) + integer(s.lo) == integer(a) + integer(b));
        // Rounding to nearest does not see a power of 2: the same sum 2^900 times larger or
        // smaller has the same error, so huge and tiny sums are exact too
        const int scale = static_cast<int>(random.integer(-900, 900));
        CAPTURE(scale);
        REQUIRE(same_bits(two_sum(std::ldexp(a, scale), std::ldexp(b, scale)),
                          DoubleDouble(std::ldexp(s.hi, scale), std::ldexp(s.lo, scale))));
    }
}

TEST_CASE("two_sum: hand-worked hard cases, the order of the terms free", "[math]") {
    CHECK(same_bits(two_sum(1, 0x1p-60), DoubleDouble(1, 0x1p-60)));
    CHECK(same_bits(two_sum(0x1p-60, 1), DoubleDouble(1, 0x1p-60)));
    CHECK(same_bits(two_sum(1e300, 1e-300), DoubleDouble(1e300, 1e-300)));
    CHECK(same_bits(two_sum(1e-300, -1e300), DoubleDouble(-1e300, 1e-300)));
    // Cancellation: exact, nothing left over
    CHECK(same_bits(two_sum(1 + 0x1p-52, -1), DoubleDouble(0x1p-52, 0)));
    CHECK(two_sum(DBL_MAX, -DBL_MAX).hi == 0);
    // 0.1 + 0.2 = 0.30000000000000004 - 2^-55 exactly (Python's fractions agree)
    CHECK(same_bits(two_sum(0.1, 0.2), DoubleDouble(0x1.3333333333334p-2, -0x1p-55)));
    // The smallest subnormal is kept beside 1
    CHECK(same_bits(two_sum(1, DBL_TRUE_MIN), DoubleDouble(1, DBL_TRUE_MIN)));
    CHECK(same_bits(two_sum(DBL_TRUE_MIN, DBL_TRUE_MIN), DoubleDouble(2 * DBL_TRUE_MIN, 0)));
}

TEST_CASE("two_product: the error of a product is exact, checked in integers at every scale",
          "[math]") {
    PortableRandom random(12);
    for (int k = 0; k < 20000; ++k) {
        CAPTURE(k);
        const double a = whole(random, 31);
        const double b = whole(random, 31);
        const DoubleDouble p = two_product(a, b);
        REQUIRE(p.hi == a * b);
        REQUIRE(integer(p.hi) + integer(p.lo) == integer(a) * integer(b));
        const int scale_a = static_cast<int>(random.integer(-480, 480));
        const int scale_b = static_cast<int>(random.integer(-480, 480));
        CAPTURE(scale_a, scale_b);
        REQUIRE(same_bits(two_product(std::ldexp(a, scale_a), std::ldexp(b, scale_b)),
                          DoubleDouble(std::ldexp(p.hi, scale_a + scale_b),
                                       std::ldexp(p.lo, scale_a + scale_b))));
    }
}

TEST_CASE("two_product: full 53-bit factors agree with Dekker's product by splitting", "[math]") {
    PortableRandom random(13);
    for (int k = 0; k < 20000; ++k) {
        CAPTURE(k);
        const double a =
            std::ldexp(random.uniform(1, 2), static_cast<int>(random.integer(-400, 400)));
        const double b =
            std::ldexp(random.uniform(-2, 2), static_cast<int>(random.integer(-400, 400)));
        REQUIRE(same_bits(two_product(a, b), dekker_product(a, b)));
    }
}

TEST_CASE("two_product: hand-worked hard cases, and where its error underflows", "[math]") {
    // 0.1 * 0.1 = 0.010000000000000002 - 0x1.eb851eb851eb8p-61 exactly (Python's fractions agree)
    CHECK(same_bits(two_product(0.1, 0.1),
                    DoubleDouble(0x1.47ae147ae147cp-7, -0x1.eb851eb851eb8p-61)));
    // (1 + 2^-52)(1 - 2^-53) = 1 + 2^-53 - 2^-105, just below the tie: 1, and the rest
    CHECK(same_bits(two_product(1 + 0x1p-52, 1 - 0x1p-53), DoubleDouble(1, 0x1p-53 - 0x1p-105)));
    // (1 + 2^-52)^2 = 1 + 2^-51 + 2^-104, near the top of the range and near the bottom
    const double above_one = 1 + 0x1p-52;
    CHECK(same_bits(two_product(std::ldexp(above_one, 600), std::ldexp(above_one, 400)),
                    DoubleDouble(std::ldexp(1 + 0x1p-51, 1000), 0x1p896)));
    CHECK(same_bits(two_product(std::ldexp(above_one, -500), std::ldexp(above_one, -400)),
                    DoubleDouble(std::ldexp(1 + 0x1p-51, -900), 0x1p-1004)));
    // Below 2^-968 the error may underflow: here a b = 2^-1040 (1 + 2^-51 + 2^-104) rounds to the
    // subnormal 2^-1040, and the rest is below the smallest subnormal
    CHECK(two_product(std::ldexp(above_one, -540), std::ldexp(above_one, -500)).lo == 0);
}

TEST_CASE("DoubleDouble: sums exact where every partial sum fits, normalized always", "[math]") {
    // (1 + 2^-60) + (1 + 2^-70) and (1 + 2^-60) - (1 + 2^-61): the rests kept, the ones gone
    CHECK(same_bits(DoubleDouble(1, 0x1p-60) + DoubleDouble(1, 0x1p-70),
                    DoubleDouble(2, 0x1p-60 + 0x1p-70)));
    CHECK(same_bits(DoubleDouble(1, 0x1p-60) - DoubleDouble(1, 0x1p-61), DoubleDouble(0x1p-61, 0)));
    CHECK(same_bits(DoubleDouble(1e300) + DoubleDouble(1e-300), DoubleDouble(1e300, 1e-300)));
    PortableRandom random(14);
    for (int k = 0; k < 20000; ++k) {
        CAPTURE(k);
        // Whole numbers below 2^62 as pairs: their sums' partial sums are whole and short
        const double a = whole(random, 61);
        const double b = whole(random, static_cast<int>(random.integer(0, 12)));
        const double c = k % 2 ? -a : whole(random, 61);
        const double d = whole(random, static_cast<int>(random.integer(0, 12)));
        const DoubleDouble x = two_sum(a, b);
        const DoubleDouble y = two_sum(c, d);
        const DoubleDouble z = x + y;
        REQUIRE(integer(z.hi) + integer(z.lo) == integer(a) + integer(b) + integer(c) + integer(d));
        REQUIRE(normalized(z));
        const DoubleDouble w = x - y;
        REQUIRE(integer(w.hi) + integer(w.lo) == integer(a) + integer(b) - integer(c) - integer(d));
    }
}

TEST_CASE("DoubleDouble: products within their bound of an independent evaluation", "[math]") {
    // (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60, which a pair holds exactly
    CHECK(same_bits(DoubleDouble(1 + 0x1p-30) * DoubleDouble(1 + 0x1p-30),
                    DoubleDouble(1 + 0x1p-29, 0x1p-60)));
    // (1 + 2^-60)^2 = 1 + 2^-59 + 2^-120: 2^-120 is below the pair's last bit
    CHECK(same_bits(DoubleDouble(1, 0x1p-60) * DoubleDouble(1, 0x1p-60), DoubleDouble(1, 0x1p-59)));
    PortableRandom random(15);
    for (int k = 0; k < 20000; ++k) {
        CAPTURE(k);
        const DoubleDouble x = two_product(random.uniform(-2, 2), random.uniform(0.5, 1));
        const DoubleDouble y = two_product(random.uniform(-2, 2), random.uniform(0.5, 1));
        const DoubleDouble z = x * y;
        REQUIRE(normalized(z));
        // The four partial products exactly, summed smallest first: within some kU^2 of the
        // product, as z must be (a few kU^2, Joldes, Muller, Popescu 2017)
        const DoubleDouble reference = two_product(x.lo, y.lo) +
                                       (two_product(x.lo, y.hi) + two_product(x.hi, y.lo)) +
                                       two_product(x.hi, y.hi);
        const DoubleDouble bound(8 * kU * kU * std::abs(reference.hi));
        REQUIRE(abs(z - reference) <= bound);
    }
}

TEST_CASE("DoubleDouble: square roots", "[math]") {
    // The root of x^2 taken exactly is x itself, whatever x
    PortableRandom random(16);
    for (int k = 0; k < 20000; ++k) {
        const double x =
            std::ldexp(random.uniform(1, 2), static_cast<int>(random.integer(-400, 400)));
        CAPTURE(k, x);
        REQUIRE(same_bits(sqrt(two_product(x, x)), DoubleDouble(x)));
    }
    // sqrt(2) to 106 bits: hi the double root, lo the rest (Python's decimal, 80 digits)
    const DoubleDouble root = sqrt(DoubleDouble(2.0));
    CHECK(root.hi == 0x1.6a09e667f3bcdp+0);
    CHECK(std::abs(root.lo - -0x1.bdd3413b26456p-54) <= 0x1p-106);
    CHECK(abs(root * root - DoubleDouble(2.0)) <= DoubleDouble(8 * kU * kU));
    CHECK(sqrt(DoubleDouble(0.0)).hi == 0);
    CHECK(std::isnan(sqrt(DoubleDouble(-1.0)).hi));
    CHECK(sqrt(DoubleDouble(kInf)).hi == kInf);
    CHECK(length(DoubleDoubleVec3(3, 4, 12)) == DoubleDouble(13.0));
}

TEST_CASE("DoubleDouble: comparisons see the rest, and NaN compares false", "[math]") {
    const DoubleDouble one(1.0);
    const DoubleDouble above(1, 0x1p-60);
    const DoubleDouble below(1, -0x1p-60);
    CHECK(above > one);
    CHECK(below < one);
    CHECK(below < above);
    CHECK(one <= one);
    CHECK(one >= one);
    CHECK_FALSE(above <= one);
    CHECK(above != one);
    const DoubleDouble nan(std::nan(""));
    CHECK_FALSE(nan < one);
    CHECK_FALSE(nan <= one);
    CHECK_FALSE(nan >= one);
    CHECK_FALSE(nan == nan);
    CHECK(nan != nan);
    CHECK(DoubleDouble(-kInf) < below);
}

TEST_CASE("DoubleDouble: infinities and overflow stay what a double makes of them", "[math]") {
    CHECK(is_infinite(DoubleDouble(kInf) + DoubleDouble(1.0)));
    CHECK(std::isnan((DoubleDouble(kInf) - DoubleDouble(kInf)).hi));
    CHECK(std::isnan((DoubleDouble(kInf) * DoubleDouble(0.0)).hi));
    CHECK((DoubleDouble(DBL_MAX) * DoubleDouble(2.0)).hi == kInf);
    CHECK((DoubleDouble(DBL_MAX) + DoubleDouble(DBL_MAX)).hi == kInf);
    CHECK(abs(DoubleDouble(-kInf)).hi == kInf);
    CHECK_FALSE(is_finite(DoubleDouble(std::nan(""))));
}

TEST_CASE("DoubleDouble: near a tolerance's edge the rest decides", "[math]") {
    // The expectation 1 + 2^-60 and the tolerance 2^-53: 1 - 2^-53 is 2^-60 beyond it, though
    // its distance from the double 1 is the tolerance exactly.
    const DoubleDouble expected = two_sum(1, 0x1p-60);
    const DoubleDouble tolerance(0x1p-53);
    CHECK(std::abs((1 - 0x1p-53) - 1.0) <= 0x1p-53);
    CHECK_FALSE(abs(DoubleDouble(1 - 0x1p-53) - expected) <= tolerance);
    // 1 + 2^-52 is 2^-52 - 2^-60 from it: on the edge of that tolerance, and so within it
    const DoubleDouble edge(0x1p-52 - 0x1p-60);
    CHECK(abs(DoubleDouble(1 + 0x1p-52) - expected) <= edge);
    CHECK_FALSE(abs(DoubleDouble(1 + 0x1p-52) - expected) < edge);
    CHECK_FALSE(std::abs((1 + 0x1p-52) - 1.0) <= 0x1p-52 - 0x1p-60);
}
