#pragma once

// Intersection tests beyond the lecture: the reference renderer, the oracle studies and the
// benchmarks use them; students meet them in docs/stage3.md.

#include <optional>

#include "stages/3_intersect/intersect.h"

namespace raystep {

/// Watertight ray-triangle test (Woop, Benthin, Wald 2013, JCGT 2(1)): a ray through an edge or
/// vertex shared by two triangles hits at least one of them, whatever the rounding. Same
/// contract as intersect_triangle.
std::optional<Hit> intersect_triangle_watertight(const Ray& ray, const Triangle& triangle);

/// Möller-Trumbore (1997): Cramer's rule rearranged so that two cross products serve all three
/// unknowns. Same contract as intersect_triangle.
std::optional<Hit> intersect_triangle_moller_trumbore(const Ray& ray, const Triangle& triangle);

/// The quadratic as first written, t = (-b -+ sqrt(b^2 - 4 a c)) / 2a: kept to measure what the
/// stable forms fix. Same contract as intersect_sphere, except accuracy.
std::optional<Hit> intersect_sphere_textbook(const Ray& ray, const Sphere& sphere);

/// The stable roots q / a and c / q the lecture asks for, with the discriminant b^2 - a c as
/// written: what a student's intersect_sphere is expected to be. Same contract as
/// intersect_sphere, except accuracy for small spheres far away.
std::optional<Hit> intersect_sphere_stable_roots(const Ray& ray, const Sphere& sphere);

}  // namespace raystep
