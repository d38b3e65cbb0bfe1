// Möller-Trumbore (1997), "Fast, minimum storage ray-triangle intersection", JGT 2(1).

#include "solutions/3_intersect/hit_building.h"
#include "solutions/3_intersect/intersect_methods.h"
#include "solutions/3_intersect/single_precision.h"

namespace raystep {

namespace {

// Written once for double and float (hit_building.h).
template <class RayType, class TriangleType, class Real = decltype(RayType::t_min)>
std::optional<Hit> moller_trumbore(const RayType& ray, const TriangleType& tri) {
    // Cramer's rule for A + t D = p0 + beta e1 + gamma e2, sharing p = D x e2 and q = s x e1
    // between the determinants.
    const auto e1 = tri.p1 - tri.p0;
    const auto e2 = tri.p2 - tri.p0;
    const auto p = glm::cross(ray.direction, e2);
    const Real det = glm::dot(e1, p);
    if (det == 0) return std::nullopt;  // parallel ray, zero direction or zero area
    const Real inverse = 1 / det;

    const auto s = ray.origin - tri.p0;
    const Real beta = glm::dot(s, p) * inverse;
    if (!(beta >= 0 && beta <= 1)) return std::nullopt;
    const auto q = glm::cross(s, e1);
    const Real gamma = glm::dot(ray.direction, q) * inverse;
    if (!(gamma >= 0 && beta + gamma <= 1)) return std::nullopt;
    const Real t = glm::dot(e2, q) * inverse;
    if (!in_ray_range(ray, t)) return std::nullopt;
    return triangle_hit(tri, t, beta, gamma);
}

}  // namespace

std::optional<Hit> intersect_triangle_moller_trumbore(const Ray& ray, const Triangle& tri) {
    return moller_trumbore(ray, tri);
}

std::optional<Hit> intersect_triangle_moller_trumbore_float(const Ray& ray, const Triangle& tri) {
    return moller_trumbore(FloatRay(ray), FloatTriangle(tri));
}

}  // namespace raystep
