#pragma once

#include "base/math/portable_random.h"
#include "base/scene/shapes.h"
#include "stages/2_rays/ray.h"

namespace raystep {

// Rays and primitives that meet at a known t, every number a short dyadic fraction (a few bits
// over a power of two): every product, sum and quotient a correct test makes of them is exact,
// so every correct test reports that t exactly, whatever its form (Cramer's rule, Moller-Trumbore,
// a plane then its edges, the stable or the textbook quadratic, the geometric sphere test). Stage
// 3's contract edges are drawn from them (stage3_contract_edges.h), where the oracle's "either
// answer near a boundary" must not apply.

/// A multiple of 1/8 in [-extent, extent].
double dyadic(PortableRandom& random, double extent);

/// A point whose coordinates are each dyadic(random, extent).
Vec3 dyadic_point(PortableRandom& random, double extent);

/// A ray that reaches `point` at `t`, a multiple of 1/4 in [1, 8]: its component along `axis` is
/// +-1, +-2 or +-4, the largest of the three, the other two multiples of 1/8 in [-1, 1], or 0 when
/// `along_axis`. Its range is [0, infinity).
Ray dyadic_ray_to(PortableRandom& random, const Vec3& point, int axis, bool along_axis, double& t);

/// A triangle in the plane through `point` normal to `axis`, `point` strictly inside it (each
/// barycentric at least 1/8), its vertices in either order, its normal (p1 - p0) x (p2 - p0) a
/// power of two from 1/2 to 32 along the axis.
Triangle dyadic_triangle_around(PortableRandom& random, const Vec3& point, int axis);

/// The plane through `point` normal to `axis`: its normal +-2^j along the axis, its point another
/// dyadic point of the plane.
Plane dyadic_plane_through(PortableRandom& random, const Vec3& point, int axis);

/// A sphere that a ray along `axis`, going the way of `sign`, enters at `point`: radius s with the
/// ray through its centre, or 5 s with the centre 3 s off the ray (a 3-4-5 triangle), s a power of
/// two from 1/4 to 2. `chord` is set to the distance from where the ray enters to where it
/// leaves: 2 s or 8 s.
Sphere dyadic_sphere_entered_at(PortableRandom& random, const Vec3& point, int axis, double sign,
                                double& chord);

}  // namespace raystep
