// Stage 3 reference solution: lecture method 2, ray-plane then 3D edge half-spaces.

#include "solutions/3_intersect/hit_building.h"

namespace raystep {

namespace {

// The inward normal of the edge a -> b: the part of (opposite - a) perpendicular to the edge.
// Zero for a zero-length edge or a collinear opposite vertex.
Vec3 inward_normal(const Vec3& a, const Vec3& b, const Vec3& opposite) {
    const Vec3 edge = b - a;
    const double edge_length = glm::length(edge);
    if (edge_length == 0.0) return Vec3(0.0);
    const Vec3 e = edge / edge_length;
    const Vec3 to_opposite = opposite - a;
    return to_opposite - glm::dot(to_opposite, e) * e;
}

}  // namespace

std::optional<Hit> intersect_triangle_halfspaces(const Ray& ray, const Triangle& tri) {
    // Step 1: where the ray crosses the supporting plane
    const std::optional<PlaneCrossing> crossing = cross_supporting_plane(ray, tri);
    if (!crossing) return std::nullopt;  // parallel, a zero direction or area, or out of range
    const auto& [t, p, n] = *crossing;

    // One half-space per edge; the distance to the edge as a fraction of the opposite vertex's
    // distance is that vertex's barycentric weight.
    const Vec3 n12 = inward_normal(tri.p1, tri.p2, tri.p0);
    const Vec3 n20 = inward_normal(tri.p2, tri.p0, tri.p1);
    const Vec3 n01 = inward_normal(tri.p0, tri.p1, tri.p2);
    const double d0 = glm::dot(p - tri.p1, n12);
    const double d1 = glm::dot(p - tri.p2, n20);
    const double d2 = glm::dot(p - tri.p0, n01);
    if (!(d0 >= 0.0 && d1 >= 0.0 && d2 >= 0.0)) return std::nullopt;  // also rejects NaN
    const double beta = d1 / glm::dot(tri.p1 - tri.p2, n20);
    const double gamma = d2 / glm::dot(tri.p2 - tri.p0, n01);
    return triangle_hit(tri, t, beta, gamma);
}

}  // namespace raystep
