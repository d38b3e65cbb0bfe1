// Stage 3 reference solution: lecture method 1, ray-plane then a 2D inside test.

#include <cmath>

#include "solutions/3_intersect/hit_building.h"
#include "solutions/3_intersect/single_precision.h"

namespace raystep {

namespace {

// The 2D cross product of (a - o) and (b - o) in the kept coordinates x, y: twice the signed
// area of the triangle o a b.
template <class Vector>
auto signed_area2(const Vector& o, const Vector& a, const Vector& b, int x, int y) {
    return (a[x] - o[x]) * (b[y] - o[y]) - (a[y] - o[y]) * (b[x] - o[x]);
}

// Written once for double and float (hit_building.h).
template <class RayType, class TriangleType, class Real = decltype(RayType::t_min)>
std::optional<Hit> projection(const RayType& ray, const TriangleType& tri) {
    // Step 1: where the ray crosses the supporting plane
    const auto crossing = cross_supporting_plane(ray, tri);
    if (!crossing) return std::nullopt;  // parallel, a zero direction or area, or out of range
    const auto& [t, p, n] = *crossing;

    // Drop the axis where |n| is largest; keeping (z+1, z+2) in cyclic order preserves the
    // orientation, so the projected triangle's area has the sign of n[z].
    const auto m = glm::abs(n);
    const int z = (m.x >= m.y && m.x >= m.z) ? 0 : (m.y >= m.z ? 1 : 2);
    const int x = (z + 1) % 3;
    const int y = (z + 2) % 3;

    // Inside: p is on the inner side of every edge, or on it.
    const Real area = signed_area2(tri.p0, tri.p1, tri.p2, x, y);
    const Real w0 = signed_area2(tri.p1, tri.p2, p, x, y);  // opposite p0
    const Real w1 = signed_area2(tri.p2, tri.p0, p, x, y);  // opposite p1
    const Real w2 = signed_area2(tri.p0, tri.p1, p, x, y);  // opposite p2
    const bool inside =
        area > 0 ? (w0 >= 0 && w1 >= 0 && w2 >= 0) : (w0 <= 0 && w1 <= 0 && w2 <= 0);
    if (!inside) return std::nullopt;
    return triangle_hit(tri, t, w1 / area, w2 / area);
}

}  // namespace

std::optional<Hit> intersect_triangle_projection(const Ray& ray, const Triangle& tri) {
    return projection(ray, tri);
}

std::optional<Hit> intersect_triangle_projection_float(const Ray& ray, const Triangle& tri) {
    return projection(FloatRay(ray), FloatTriangle(tri));
}

}  // namespace raystep
