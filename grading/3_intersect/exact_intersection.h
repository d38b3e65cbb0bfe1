#pragma once

#include <vector>

#include "app/check/ray_case.h"

namespace raystep {

// The exact oracle for stage 3: what intersect.h's contract says a ray and a primitive do, decided
// in exact arithmetic (CGAL's exact kernel), with t, the normal and the barycentrics rounded
// correctly to the nearest double (MPFR), and the tolerances a correct double-precision test is
// allowed. It links CGAL; this header does not include it.

/// The rounding budget every tolerance is built from. A backward-stable double-precision test
/// answers exactly for inputs moved by a few roundings of their magnitude; we allow each input
/// coordinate to move by kRoundingUlps units of double rounding (2^-53) of the problem's largest
/// coordinate, and call a case near a boundary when so small a move could change the answer.
/// docs/case-files.md, "Where the tolerances come from", derives every tolerance from it.
inline constexpr double kRoundingUlps = 64.0;

/// The exact answer for one ray and one triangle: a hit when the ray's line meets the closed
/// triangle at t in [t_min, t_max]; a miss for a zero direction, a degenerate (collinear)
/// triangle, or a ray parallel to the triangle's plane.
Expectation expect_triangle(const Ray& ray, const Triangle& triangle);

/// The exact answer for one ray and one sphere: the smaller root in range, else the larger; a
/// miss for a zero direction or a radius that is not positive.
Expectation expect_sphere(const Ray& ray, const Sphere& sphere);

/// The exact answer for one ray and one plane; a miss for a parallel ray, a zero direction or a
/// zero normal.
Expectation expect_plane(const Ray& ray, const Plane& plane);

/// Whichever of the three the shape needs.
Expectation expect_primitive(const Ray& ray, const CaseShape& shape);

/// The exact closest hit over several primitives: the index of the primitive whose exact hit has
/// the smallest t (ties to the earlier primitive in closest_hit's order: spheres, triangles,
/// planes, each in list order), or -1 when the ray misses them all.
int exact_closest_primitive(const Ray& ray, const std::vector<CaseShape>& shapes);

}  // namespace raystep
