// Stage 3 reference solution: lecture method 3, Cramer's rule with early exits.

#include "solutions/3_intersect/hit_building.h"
#include "solutions/3_intersect/single_precision.h"

namespace raystep {

namespace {

// det[a b c] = a . (b x c)
template <class Vector>
auto det(const Vector& a, const Vector& b, const Vector& c) {
    return glm::dot(a, glm::cross(b, c));
}

// Written once for double and float (hit_building.h).
template <class RayType, class TriangleType, class Real = decltype(RayType::t_min)>
std::optional<Hit> cramer(const RayType& ray, const TriangleType& tri) {
    // beta (p0 - p1) + gamma (p0 - p2) + t D = p0 - A
    const auto c0 = tri.p0 - tri.p1;
    const auto c1 = tri.p0 - tri.p2;
    const auto& c2 = ray.direction;
    const auto rhs = tri.p0 - ray.origin;
    const Real m = det(c0, c1, c2);
    if (m == 0) return std::nullopt;  // parallel ray, zero direction or zero area

    // Each unknown in turn, leaving at the first one out of range; written to reject NaN.
    const Real t = det(c0, c1, rhs) / m;
    if (!in_ray_range(ray, t)) return std::nullopt;
    const Real gamma = det(c0, rhs, c2) / m;
    if (!(gamma >= 0 && gamma <= 1)) return std::nullopt;
    const Real beta = det(rhs, c1, c2) / m;
    if (!(beta >= 0 && beta <= 1 - gamma)) return std::nullopt;
    return triangle_hit(tri, t, beta, gamma);
}

}  // namespace

std::optional<Hit> intersect_triangle_cramer(const Ray& ray, const Triangle& tri) {
    return cramer(ray, tri);
}

std::optional<Hit> intersect_triangle_cramer_float(const Ray& ray, const Triangle& tri) {
    return cramer(FloatRay(ray), FloatTriangle(tri));
}

}  // namespace raystep
