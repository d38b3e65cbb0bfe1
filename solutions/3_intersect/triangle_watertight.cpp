// Woop, Benthin, Wald (2013), "Watertight Ray/Triangle Intersection", JCGT 2(1).

#include <utility>

#include "solutions/3_intersect/hit_building.h"
#include "solutions/3_intersect/intersect_methods.h"
#include "solutions/3_intersect/single_precision.h"

namespace raystep {

namespace {

// Why it is watertight: the ray becomes the +z axis of a sheared frame, and each edge function
// is a 2D cross product of two sheared vertices. A vertex's sheared coordinates depend only on
// the vertex and the ray, so the two triangles that share an edge compute that edge's function
// from the same numbers, once as x1*y2 - y1*x2 and once as x2*y1 - y2*x1: exact negations of
// each other (products commute, and rounding to nearest is symmetric). A point on the rounded
// edge is 0 for both and counts as inside; off it, exactly one side accepts it. This needs the
// products rounded separately, which is why the build passes -ffp-contract=off (a fused
// multiply-add would round one product and not the other).
//
// Written once for double and float (hit_building.h).
template <class RayType, class TriangleType, class Real = decltype(RayType::t_min)>
std::optional<Hit> watertight(const RayType& ray, const TriangleType& tri) {
    // Name the axes so that z is the direction's largest component; swapping x and y when
    // D.z < 0 keeps the triangle's winding.
    const auto& d = ray.direction;
    const auto magnitude = glm::abs(d);
    const int kz = magnitude.x > magnitude.y ? (magnitude.x > magnitude.z ? 0 : 2)
                                             : (magnitude.y > magnitude.z ? 1 : 2);
    if (d[kz] == 0) return std::nullopt;  // a zero direction
    int kx = (kz + 1) % 3;
    int ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);

    // The shear that takes D to (0, 0, 1)
    const Real sx = d[kx] / d[kz];
    const Real sy = d[ky] / d[kz];
    const Real sz = 1 / d[kz];

    // The vertices relative to the origin, sheared
    const auto a = tri.p0 - ray.origin;
    const auto b = tri.p1 - ray.origin;
    const auto c = tri.p2 - ray.origin;
    const Real ax = a[kx] - sx * a[kz];
    const Real ay = a[ky] - sy * a[kz];
    const Real bx = b[kx] - sx * b[kz];
    const Real by = b[ky] - sy * b[kz];
    const Real cx = c[kx] - sx * c[kz];
    const Real cy = c[ky] - sy * c[kz];

    // Edge functions: the scaled barycentric weights of p0, p1, p2. Mixed signs: outside.
    const Real u = cx * by - cy * bx;
    const Real v = ax * cy - ay * cx;
    const Real w = bx * ay - by * ax;
    // The six comparisons are joined with | rather than ||: each || is a branch on the ray,
    // which the processor mispredicts about as often as not (most tests in a BVH leaf miss, each
    // by a different edge), and | leaves one. A NaN compares false either way.
    const bool some_negative = (u < 0) | (v < 0) | (w < 0);
    const bool some_positive = (u > 0) | (v > 0) | (w > 0);
    if (some_negative & some_positive) return std::nullopt;
    const Real det = u + v + w;
    if (det == 0) return std::nullopt;  // the ray lies in the plane, or zero area

    // Distance along the ray, from the sheared z coordinates
    const Real t = (u * sz * a[kz] + v * sz * b[kz] + w * sz * c[kz]) / det;
    if (!in_ray_range(ray, t)) return std::nullopt;
    return triangle_hit(tri, t, v / det, w / det);
}

}  // namespace

std::optional<Hit> intersect_triangle_watertight(const Ray& ray, const Triangle& tri) {
    return watertight(ray, tri);
}

std::optional<Hit> intersect_triangle_watertight_float(const Ray& ray, const Triangle& tri) {
    return watertight(FloatRay(ray), FloatTriangle(tri));
}

}  // namespace raystep
