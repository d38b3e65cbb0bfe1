// Stage 3: ray-triangle by projection to 2D (lecture method 1). Handout: docs/stage3.md.

#include <cmath>

#include "stages/1_vectors/vectors.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

namespace {

// Twice the signed area of the 2D triangle (o, a, b), in the kept coordinates x and y.
double signed_area2(const Vec3& o, const Vec3& a, const Vec3& b, int x, int y) {
    return (a[x] - o[x]) * (b[y] - o[y]) - (a[y] - o[y]) * (b[x] - o[x]);
}

}  // namespace

std::optional<Hit> intersect_triangle_projection(const Ray& ray, const Triangle& tri) {
    // 1. The triangle's plane; a zero normal is a degenerate triangle
    const Vec3 n = cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    if (n == Vec3(0.0)) return std::nullopt;

    // 2. Where the ray crosses it
    const double denominator = dot(ray.direction, n);
    if (denominator == 0.0) return std::nullopt;  // parallel, or a zero direction
    const double t = dot(tri.p0 - ray.origin, n) / denominator;
    if (!(t >= ray.t_min && t <= ray.t_max) || !std::isfinite(t)) return std::nullopt;
    const Vec3 p = ray.at(t);

    // 3. Drop the coordinate in which |n| is largest. Keeping the other two in cyclic order
    //    (z + 1, z + 2) keeps the orientation: the 2D area has the sign of n[z].
    const Vec3 m(std::abs(n.x), std::abs(n.y), std::abs(n.z));
    const int z = (m.x >= m.y && m.x >= m.z) ? 0 : (m.y >= m.z ? 1 : 2);
    const int x = (z + 1) % 3;
    const int y = (z + 2) % 3;

    // 4. Inside: on the inner side of every edge, or on it
    const double area = signed_area2(tri.p0, tri.p1, tri.p2, x, y);
    const double a0 = signed_area2(tri.p1, tri.p2, p, x, y);  // opposite p0
    const double a1 = signed_area2(tri.p2, tri.p0, p, x, y);  // opposite p1
    const double a2 = signed_area2(tri.p0, tri.p1, p, x, y);  // opposite p2
    const bool inside = area > 0.0 ? (a0 >= 0.0 && a1 >= 0.0 && a2 >= 0.0)
                                   : (a0 <= 0.0 && a1 <= 0.0 && a2 <= 0.0);
    if (!inside || area == 0.0) return std::nullopt;

    // 5. Barycentrics as ratios of areas
    return Hit{t, normalize(n), a1 / area, a2 / area};
}

}  // namespace raystep
