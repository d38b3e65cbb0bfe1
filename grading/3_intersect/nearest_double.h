#pragma once

// Correct rounding of exact values to doubles, with MPFR. CGAL::to_double of a lazy exact
// number is only as good as its interval approximation (1e-5 relative), far from enough to score
// a t in ulps; these round the exact value itself.

#include <gmp.h>
#include <mpfr.h>

namespace raystep {

/// The double nearest to q, ties to even, as IEEE arithmetic rounds it (subnormals included);
/// plus or minus infinity beyond the largest double.
double nearest_double(mpq_srcptr q);

/// The double nearest to a root of a t^2 + 2 b t + c = 0, with a > 0 and disc = b^2 - a c >= 0
/// given: the smaller root (-b - sqrt(disc)) / a when `smaller`, else the larger. Exact when disc
/// is the square of a rational; otherwise evaluated in the stable form at rising precision until
/// the rounding is certain (Ziv's strategy, with mpfr_can_round).
double nearest_double_of_root(mpq_srcptr a, mpq_srcptr b, mpq_srcptr c, mpq_srcptr disc,
                              bool smaller);

/// Sets `out` to that root at out's precision, in the stable form q = -(b + sign(b) sqrt(disc)),
/// roots q / a and c / q: no step cancels, so the result carries at most 8 roundings of that
/// precision. Needs disc > 0 or b != 0 (else q = 0: use the exact path).
void evaluate_root(mpfr_ptr out, mpq_srcptr a, mpq_srcptr b, mpq_srcptr c, mpq_srcptr disc,
                   bool smaller);

}  // namespace raystep
