#pragma once

// The oracle's exact arithmetic: CGAL's kernel with exact predicates and exact constructions.
// Its numbers are lazy: intervals first, exact rationals only when an interval cannot decide, so
// most signs cost little. Included by the oracle's .cpp files only.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <gmpxx.h>

#include "base/math/types.h"
#include "grading/3_intersect/nearest_double.h"

namespace raystep::exact {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Number = Kernel::FT;

/// Every double is a rational, so these conversions are exact.
inline Point point(const Vec3& p) {
    return {p.x, p.y, p.z};
}
inline Vector vector(const Vec3& v) {
    return {v.x, v.y, v.z};
}

// CGAL's exact rational is mpq_class or CGAL::Gmpq, depending on how CGAL was configured.
inline mpq_srcptr as_mpq(const mpq_class& q) {
    return q.get_mpq_t();
}
inline mpq_srcptr as_mpq(const CGAL::Gmpq& q) {
    return q.mpq();
}

/// The exact value's nearest double (not CGAL::to_double, which rounds the interval).
inline double rounded(const Number& x) {
    return nearest_double(as_mpq(CGAL::exact(x)));
}

/// A double approximation, good to about 1e-5 relative: enough to compare a value with a
/// tolerance, never to score.
inline double approximate(const Number& x) {
    return CGAL::to_double(x);
}

}  // namespace raystep::exact
