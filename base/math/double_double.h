#pragma once

#include <cfloat>
#include <cmath>

namespace raystep {

// A number carried as the unevaluated sum hi + lo of two doubles (Dekker 1971, "A floating-point
// technique for extending the available precision"), some 106 bits: the arithmetic of the judges
// (app/grade/, grading/*/) that hold a student's double against an expectation decided with more
// bits than a double has. Not long double, because `raystep grade` judges on the student's laptop,
// where long double is a double (MSVC, Apple silicon), 64 bits (x86-64 Linux) or 113 (arm64 Linux),
// and a case within half an ulp of its tolerance would get each platform's own verdict. Every
// operation below is a fixed sequence of IEEE-754 double operations (+, -, *, /, sqrt, fma), each
// correctly rounded, so every platform computes the same bits and gives the same verdict.
//
// That holds where each operation rounds once, to double: no x87 excess precision (every 64-bit
// target evaluates double in double) and no multiply-add contracted behind the code's back
// (raystep_set_compile_options turns contraction off; MSVC does not contract). Each building
// block's exactness is tested on hard cases in base/math/tests/double_double_test.cpp
// (`build/release/bin/raystep_base_tests "[math]"`).
#if defined(FLT_EVAL_METHOD)
static_assert(FLT_EVAL_METHOD <= 0, "double-double arithmetic needs double rounded to double");
#endif

/// The value hi + lo, hi that value rounded to the nearest double and |lo| at most half an ulp of
/// hi, so that comparing (hi, lo) in that order compares the values. An infinite or NaN value is
/// its hi alone, with lo 0. The sign of a zero is not kept through arithmetic.
struct DoubleDouble {
    double hi = 0.0;
    double lo = 0.0;

    constexpr DoubleDouble() = default;
    /// x, exactly.
    constexpr explicit DoubleDouble(double x) : hi(x) {}
    /// The pair as given: `high` must be high + low rounded to nearest, as two_sum's answer is.
    constexpr DoubleDouble(double high, double low) : hi(high), lo(low) {}
    /// The nearest double.
    constexpr explicit operator double() const { return hi; }
};

/// a + b exactly, as s + e with s = a + b rounded: Knuth's TwoSum (The Art of Computer
/// Programming, vol. 2, 4.2.2, Theorem B; Moller 1965), six operations, for any finite a and b
/// whatever their order of magnitude.
inline DoubleDouble two_sum(double a, double b) {
    const double s = a + b;
    const double b_in_s = s - a;
    const double a_in_s = s - b_in_s;
    return {s, (a - a_in_s) + (b - b_in_s)};
}

/// a + b exactly where |a| >= |b| (or a is 0): Dekker's Fast2Sum, three operations.
inline DoubleDouble fast_two_sum(double a, double b) {
    const double s = a + b;
    return {s, b - (s - a)};
}

/// a b exactly, as p + e with p = a b rounded: a b - p is a double, and the fma rounds it once
/// (Muller et al., Handbook of Floating-Point Arithmetic, 2nd ed., 2018, "2MultFMA"). Exact
/// wherever e does not underflow, which |a b| >= 2^-968 ensures.
inline DoubleDouble two_product(double a, double b) {
    const double p = a * b;
    return {p, std::fma(a, b, -p)};
}

inline DoubleDouble operator-(const DoubleDouble& x) {
    return {-x.hi, -x.lo};
}

/// The sum within (3u^2 + 13u^3) of itself, u = 2^-53: Joldes, Muller, Popescu 2017, "Tight and
/// rigorous error bounds for basic building blocks of double-word arithmetic", ACM TOMS 44(2),
/// Algorithm 6 (AccurateDWPlusDW). Cancellation costs it nothing: the high parts add exactly.
inline DoubleDouble operator+(const DoubleDouble& x, const DoubleDouble& y) {
    const DoubleDouble s = two_sum(x.hi, y.hi);
    // An infinite or NaN sum is its hi alone: an infinity's error term would be NaN.
    if (!std::isfinite(s.hi)) return DoubleDouble(s.hi);
    const DoubleDouble t = two_sum(x.lo, y.lo);
    const DoubleDouble v = fast_two_sum(s.hi, s.lo + t.hi);
    return fast_two_sum(v.hi, t.lo + v.lo);
}

inline DoubleDouble operator-(const DoubleDouble& x, const DoubleDouble& y) {
    return x + -y;
}

/// The product within a few u^2 of itself: the same paper, Algorithm 12 (DWTimesDW3), the low
/// terms gathered by two fmas.
inline DoubleDouble operator*(const DoubleDouble& x, const DoubleDouble& y) {
    const DoubleDouble c = two_product(x.hi, y.hi);
    if (!std::isfinite(c.hi)) return DoubleDouble(c.hi);
    const double low_terms = std::fma(x.lo, y.hi, std::fma(x.hi, y.lo, x.lo * y.lo));
    return fast_two_sum(c.hi, c.lo + low_terms);
}

/// The square root within a few u^2 of itself: the double root r and one Newton step,
/// r + (x - r^2) / 2r (Karp, Markstein 1997, "High precision division and square root", ACM TOMS
/// 23(4)). NaN below 0, x itself at 0 and infinity.
inline DoubleDouble sqrt(const DoubleDouble& x) {
    const double root = std::sqrt(x.hi);
    // Written so that a NaN takes this way too
    if (!(x.hi > 0) || !std::isfinite(x.hi)) return DoubleDouble(root);
    // x - r^2, exact but for its last rounding: r^2 is two_product's pair, and x.hi - its hi is
    // exact, the two within a factor 2 of each other (Sterbenz)
    const DoubleDouble square = two_product(root, root);
    const double residual = ((x.hi - square.hi) - square.lo) + x.lo;
    return fast_two_sum(root, residual / (2 * root));
}

/// x 2^exponent, exact unless a part leaves the range of doubles (lo underflows first).
inline DoubleDouble ldexp(const DoubleDouble& x, int exponent) {
    return {std::ldexp(x.hi, exponent), std::ldexp(x.lo, exponent)};
}

inline DoubleDouble abs(const DoubleDouble& x) {
    return x.hi < 0 ? -x : x;
}

inline bool is_finite(const DoubleDouble& x) {
    return std::isfinite(x.hi);
}

inline bool is_infinite(const DoubleDouble& x) {
    return std::isinf(x.hi);
}

// The comparisons of values with normalized pairs, each false where either side is NaN, as a
// double's are (!= true).
inline bool operator==(const DoubleDouble& x, const DoubleDouble& y) {
    return x.hi == y.hi && x.lo == y.lo;
}

inline bool operator!=(const DoubleDouble& x, const DoubleDouble& y) {
    return !(x == y);
}

inline bool operator<(const DoubleDouble& x, const DoubleDouble& y) {
    return x.hi < y.hi || (x.hi == y.hi && x.lo < y.lo);
}

inline bool operator<=(const DoubleDouble& x, const DoubleDouble& y) {
    return x.hi < y.hi || (x.hi == y.hi && x.lo <= y.lo);
}

inline bool operator>(const DoubleDouble& x, const DoubleDouble& y) {
    return y < x;
}

inline bool operator>=(const DoubleDouble& x, const DoubleDouble& y) {
    return y <= x;
}

}  // namespace raystep
