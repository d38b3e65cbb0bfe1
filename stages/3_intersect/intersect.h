#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "base/scene/shapes.h"
#include "stages/2_rays/ray.h"
#include "stages/3_intersect/hit.h"

namespace raystep {

// Stage 3: ray-object intersection. Handout: docs/stage3.md.
//
// Every test returns the hit with a finite t in [ray.t_min, ray.t_max] (both ends included), or
// nullopt on a miss. Points on a triangle's edges and vertices belong to the triangle.
// Degenerate input (a zero direction, a zero-area triangle, a zero radius) is a miss, never a
// NaN. Surfaces are two-sided: a ray meets a triangle or plane from either side.
//
// The domain: coordinates and direction components of magnitude 1e-100 to 1e100, or 0. The
// plane and triangle tests multiply three of them, and beyond that range the product overflows
// or underflows a double. The sphere's quadratic multiplies four (b^2 is (D . f)^2): for
// intersect_sphere the range is 1e-75 to 1e75.

/// Ray-plane: t = (p0 - A) . N / (D . N). A ray parallel to the plane misses it, even when it
/// lies in it.
std::optional<Hit> intersect_plane(const Ray& ray, const Plane& plane);

/// Ray-triangle, lecture method 1: intersect the triangle's plane, then drop the coordinate in
/// which the normal is largest and test the hit point against the three edges in 2D.
std::optional<Hit> intersect_triangle_projection(const Ray& ray, const Triangle& triangle);

/// Ray-triangle, lecture method 2: intersect the triangle's plane, then test the hit point
/// against the three edges' half-spaces in 3D, each bounded by the edge's inward normal, the
/// component of (opposite vertex - edge start) perpendicular to the edge.
std::optional<Hit> intersect_triangle_halfspaces(const Ray& ray, const Triangle& triangle);

/// Ray-triangle, lecture method 3: solve A + t D = p0 + beta (p1 - p0) + gamma (p2 - p0) for
/// beta, gamma and t by Cramer's rule, leaving as soon as one of them is out of range.
std::optional<Hit> intersect_triangle_cramer(const Ray& ray, const Triangle& triangle);

/// The triangle test that closest_hit and the renderer use: one of the three above.
std::optional<Hit> intersect_triangle(const Ray& ray, const Triangle& triangle);

/// Ray-sphere: the smaller root of |A + t D - C|^2 = r^2 within [t_min, t_max], else the larger
/// (a ray starting inside the sphere hits it from within; a tangent ray touches it at its double
/// root), computed in a form that stays accurate for spheres that are tiny, huge or far from the
/// ray's origin.
std::optional<Hit> intersect_sphere(const Ray& ray, const Sphere& sphere);

/// All the primitives of a scene, by kind, for closest_hit.
struct PrimitiveList {
    std::vector<Sphere> spheres;
    std::vector<Triangle> triangles;
    std::vector<Plane> planes;
};

enum class PrimitiveKind { sphere, triangle, plane };

/// A hit and the primitive it is on: `index` into the list of its kind.
struct PrimitiveHit {
    Hit hit;
    PrimitiveKind kind;
    std::size_t index;
};

/// The hit with the smallest t in [ray.t_min, ray.t_max] over every primitive of the list;
/// nullopt when the ray misses them all. When two hits have the same t, the primitive listed
/// first wins: spheres before triangles before planes, each in list order.
std::optional<PrimitiveHit> closest_hit(const Ray& ray, const PrimitiveList& primitives);

}  // namespace raystep
