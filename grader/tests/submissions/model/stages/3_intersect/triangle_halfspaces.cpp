// Stage 3: ray-triangle by 3D half-spaces (lecture method 2). Handout: docs/stage3.md.

#include <cmath>

#include "stages/1_vectors/vectors.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

std::optional<Hit> intersect_triangle_halfspaces(const Ray& ray, const Triangle& tri) {
    // 1. The triangle's plane, as in method 1; a zero normal is a degenerate triangle
    const Vec3 n = cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    if (n == Vec3(0.0)) return std::nullopt;
    const double denominator = dot(ray.direction, n);
    if (denominator == 0.0) return std::nullopt;
    const double t = dot(tri.p0 - ray.origin, n) / denominator;
    if (!(t >= ray.t_min && t <= ray.t_max) || !std::isfinite(t)) return std::nullopt;
    const Vec3 p = ray.at(t);

    // 2. Each edge's inward normal: the part of (opposite vertex - edge start) perpendicular to
    //    the edge. A nonzero n means no edge has zero length.
    const Vec3 n12 = perpendicular_to(tri.p0 - tri.p1, tri.p2 - tri.p1);  // edge p1 -> p2
    const Vec3 n20 = perpendicular_to(tri.p1 - tri.p2, tri.p0 - tri.p2);  // edge p2 -> p0
    const Vec3 n01 = perpendicular_to(tri.p2 - tri.p0, tri.p1 - tri.p0);  // edge p0 -> p1

    // 3. Inside all three half-spaces (written so that NaN is outside)
    const double d0 = dot(p - tri.p1, n12);
    const double d1 = dot(p - tri.p2, n20);
    const double d2 = dot(p - tri.p0, n01);
    if (!(d0 >= 0.0 && d1 >= 0.0 && d2 >= 0.0)) return std::nullopt;

    // 4. The distance to an edge as a fraction of the opposite vertex's: that vertex's weight
    const double beta = d1 / dot(tri.p1 - tri.p2, n20);
    const double gamma = d2 / dot(tri.p2 - tri.p0, n01);
    if (!std::isfinite(beta) || !std::isfinite(gamma)) return std::nullopt;
    return Hit{t, normalize(n), beta, gamma};
}

}  // namespace raystep
