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

/// The quadratic as first written, t = (-b -+ sqrt(b^2 - a c)) / a with c = f . f - r^2: kept to
/// measure what the stable form of intersect_sphere fixes. Same contract as intersect_sphere.
std::optional<Hit> intersect_sphere_textbook(const Ray& ray, const Sphere& sphere);

}  // namespace raystep
