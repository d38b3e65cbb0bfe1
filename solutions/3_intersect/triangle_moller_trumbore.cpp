// Möller-Trumbore (1997), "Fast, minimum storage ray-triangle intersection", JGT 2(1).

#include "solutions/3_intersect/intersect_methods.h"
#include "solutions/3_intersect/hit_building.h"

namespace raystep {

std::optional<Hit> intersect_triangle_moller_trumbore(const Ray& ray, const Triangle& tri) {
    // Cramer's rule for A + t D = p0 + beta e1 + gamma e2, sharing p = D x e2 and q = s x e1
    // between the determinants.
    const Vec3 e1 = tri.p1 - tri.p0;
    const Vec3 e2 = tri.p2 - tri.p0;
    const Vec3 p = glm::cross(ray.direction, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0) return std::nullopt;  // parallel ray, zero direction or zero area
    const double inverse = 1.0 / det;

    const Vec3 s = ray.origin - tri.p0;
    const double beta = glm::dot(s, p) * inverse;
    if (!(beta >= 0.0 && beta <= 1.0)) return std::nullopt;
    const Vec3 q = glm::cross(s, e1);
    const double gamma = glm::dot(ray.direction, q) * inverse;
    if (!(gamma >= 0.0 && beta + gamma <= 1.0)) return std::nullopt;
    const double t = glm::dot(e2, q) * inverse;
    if (!in_ray_range(ray, t)) return std::nullopt;
    return triangle_hit(tri, t, beta, gamma);
}

}  // namespace raystep
