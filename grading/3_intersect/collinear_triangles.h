#pragma once

#include "base/math/portable_random.h"
#include "base/scene/shapes.h"
#include "stages/2_rays/ray.h"

namespace raystep {

/// The form of a ray-triangle solve whose rounding a collinear case is drawn to trip.
enum class SolveForm {
    /// The handout's Cramer's rule: columns p0 - p1, p0 - p2 and D, det[a b c] = a . (b x c)
    cramer,
    /// Moller and Trumbore (1997): e1 = p1 - p0, e2 = p2 - p0, det = e1 . (D x e2)
    moller_trumbore
};

/// A ray and the collinear triangle it is aimed at (collinear_case).
struct CollinearCase {
    Ray ray;
    Triangle triangle;
    bool trips = false;  ///< `form` finds the rounded hit (false only after every draw missed)
};

/// A collinear triangle, its vertices short dyadic fractions so that every correct test finds its
/// normal (p1 - p0) x (p2 - p0) exactly zero, and a ray aimed at a point of it. Drawn again until
/// `form`, as written without a test for a zero normal, finds a determinant that rounds away from
/// zero and t, beta and gamma in range: a hit whose normal, a zero vector normalized, is NaN or
/// throws. Every triangle drawn is collinear, so a case that has not tripped `form` is still a
/// degenerate triangle.
CollinearCase collinear_case(PortableRandom& random, SolveForm form);

/// True when `form`, without a test for a zero normal, reports a hit of the ray on the triangle:
/// a nonzero determinant and t in [t_min, t_max], beta and gamma in range.
bool form_reports_hit(SolveForm form, const Ray& ray, const Triangle& triangle);

}  // namespace raystep
