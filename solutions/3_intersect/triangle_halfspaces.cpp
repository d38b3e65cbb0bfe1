// Stage 3 reference solution: lecture method 2, ray-plane then 3D edge half-spaces.

#include "solutions/3_intersect/hit_building.h"
#include "solutions/3_intersect/single_precision.h"

namespace raystep {

namespace {

// The inward normal of the edge a -> b: the part of (opposite - a) perpendicular to the edge.
// Zero for a zero-length edge or a collinear opposite vertex.
template <class Vector>
Vector inward_normal(const Vector& a, const Vector& b, const Vector& opposite) {
    const Vector edge = b - a;
    const auto edge_length = glm::length(edge);
    if (edge_length == 0) return Vector(0);
    const Vector e = edge / edge_length;
    const Vector to_opposite = opposite - a;
    return to_opposite - glm::dot(to_opposite, e) * e;
}

// Written once for double and float (hit_building.h).
template <class RayType, class TriangleType, class Real = decltype(RayType::t_min)>
std::optional<Hit> halfspaces(const RayType& ray, const TriangleType& tri) {
    // Step 1: where the ray crosses the supporting plane
    const auto crossing = cross_supporting_plane(ray, tri);
    if (!crossing) return std::nullopt;  // parallel, a zero direction or area, or out of range
    const auto& [t, p, n] = *crossing;

    // One half-space per edge; the distance to the edge as a fraction of the opposite vertex's
    // distance is that vertex's barycentric weight.
    const auto n12 = inward_normal(tri.p1, tri.p2, tri.p0);
    const auto n20 = inward_normal(tri.p2, tri.p0, tri.p1);
    const auto n01 = inward_normal(tri.p0, tri.p1, tri.p2);
    const Real d0 = glm::dot(p - tri.p1, n12);
    const Real d1 = glm::dot(p - tri.p2, n20);
    const Real d2 = glm::dot(p - tri.p0, n01);
    if (!(d0 >= 0 && d1 >= 0 && d2 >= 0)) return std::nullopt;  // also rejects NaN

    // A sliver whose opposite vertex rounds onto an edge's line has a zero inward normal there:
    // the point is "inside" at distance 0 of 0, and the weight 0 / 0 would be NaN. Such a
    // triangle is degenerate in this precision, a miss; the comparisons also reject NaN.
    const Real height1 = glm::dot(tri.p1 - tri.p2, n20);
    const Real height2 = glm::dot(tri.p2 - tri.p0, n01);
    if (!(height1 > 0 && height2 > 0)) return std::nullopt;
    const Real beta = d1 / height1;
    const Real gamma = d2 / height2;
    return triangle_hit(tri, t, beta, gamma);
}

}  // namespace

std::optional<Hit> intersect_triangle_halfspaces(const Ray& ray, const Triangle& tri) {
    return halfspaces(ray, tri);
}

std::optional<Hit> intersect_triangle_halfspaces_float(const Ray& ray, const Triangle& tri) {
    return halfspaces(FloatRay(ray), FloatTriangle(tri));
}

}  // namespace raystep
