// Stage 3: ray-triangle by Cramer's rule (lecture method 3). Handout: docs/stage3.md.

#include <cmath>

#include "stages/1_vectors/vectors.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

namespace {

// det[a b c] = a . (b x c)
double det(const Vec3& a, const Vec3& b, const Vec3& c) {
    return dot(a, cross(b, c));
}

}  // namespace

std::optional<Hit> intersect_triangle_cramer(const Ray& ray, const Triangle& tri) {
    // beta (p0 - p1) + gamma (p0 - p2) + t D = p0 - A
    const Vec3 c0 = tri.p0 - tri.p1;
    const Vec3 c1 = tri.p0 - tri.p2;
    const Vec3& c2 = ray.direction;
    const Vec3 rhs = tri.p0 - ray.origin;
    const double m = det(c0, c1, c2);
    if (m == 0.0) return std::nullopt;  // parallel ray, zero direction or zero area

    // One unknown at a time, leaving as soon as one is out of range (comparisons reject NaN)
    const double t = det(c0, c1, rhs) / m;
    if (!(t >= ray.t_min && t <= ray.t_max) || !std::isfinite(t)) return std::nullopt;
    const double gamma = det(c0, rhs, c2) / m;
    if (!(gamma >= 0.0 && gamma <= 1.0)) return std::nullopt;
    const double beta = det(rhs, c1, c2) / m;
    if (!(beta >= 0.0 && beta <= 1.0 - gamma)) return std::nullopt;

    // The geometric normal; an exactly collinear triangle can still get a rounding-sized m
    const Vec3 n = cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    if (n == Vec3(0.0)) return std::nullopt;
    return Hit{t, normalize(n), beta, gamma};
}

}  // namespace raystep
