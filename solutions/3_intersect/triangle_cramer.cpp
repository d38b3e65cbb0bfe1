// Stage 3 reference solution: lecture method 3, Cramer's rule with early exits.

#include "solutions/3_intersect/hit_building.h"

namespace raystep {

namespace {

// det[a b c] = a . (b x c)
double det(const Vec3& a, const Vec3& b, const Vec3& c) {
    return glm::dot(a, glm::cross(b, c));
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

    // Each unknown in turn, leaving at the first one out of range; written to reject NaN.
    const double t = det(c0, c1, rhs) / m;
    if (!in_ray_range(ray, t)) return std::nullopt;
    const double gamma = det(c0, rhs, c2) / m;
    if (!(gamma >= 0.0 && gamma <= 1.0)) return std::nullopt;
    const double beta = det(rhs, c1, c2) / m;
    if (!(beta >= 0.0 && beta <= 1.0 - gamma)) return std::nullopt;
    return triangle_hit(tri, t, beta, gamma);
}

}  // namespace raystep
