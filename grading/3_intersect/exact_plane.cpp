#include <glm/geometric.hpp>

#include "grading/3_intersect/exact_hits.h"
#include "grading/3_intersect/exact_intersection.h"
#include "grading/3_intersect/possible_answers.h"
#include "grading/3_intersect/rounding_budget.h"

namespace raystep {

namespace {

// The exact geometry of a ray and a plane.
struct PlaneGeometry {
    bool degenerate = true;  ///< a zero direction or a zero normal
    bool parallel = false;   ///< D . N = 0
    exact::Number den;       ///< D . N
    exact::Number t;
    bool in_range = false;
};

PlaneGeometry solve_plane(const Ray& ray, const Plane& plane) {
    using namespace exact;
    PlaneGeometry g;
    if (ray.direction == Vec3(0.0) || plane.normal == Vec3(0.0)) return g;
    g.degenerate = false;
    const Vector n = vector(plane.normal);
    g.den = vector(ray.direction) * n;
    if (CGAL::is_zero(g.den)) {
        g.parallel = true;
        return g;
    }
    g.t = ((point(plane.point) - point(ray.origin)) * n) / g.den;
    g.in_range = g.t >= ray.t_min && (!std::isfinite(ray.t_max) || g.t <= ray.t_max);
    return g;
}

}  // namespace

std::optional<exact::HitTime> exact::plane_hit_time(const Ray& ray, const Plane& plane) {
    const PlaneGeometry g = solve_plane(ray, plane);
    if (g.degenerate || g.parallel || !g.in_range) return std::nullopt;
    HitTime time;
    time.rational = g.t;
    return time;
}

Expectation expect_plane(const Ray& ray, const Plane& plane) {
    Expectation expected;  // a miss, away from any boundary, until shown otherwise
    const PlaneGeometry g = solve_plane(ray, plane);
    // A zero direction or normal is a miss by the contract. A parallel ray is one too, but
    // turned by a rounding it would cross.
    if (g.degenerate) return expected;
    if (g.parallel) {
        expected.near_boundary = true;
        return expected;
    }

    // The budget: the plane's point and the origin move by the slack, D and N turn by theirs.
    const double t = exact::rounded(g.t);
    const double d_length = glm::length(ray.direction);
    const double n_length = glm::length(plane.normal);
    const double den = std::abs(exact::approximate(g.den));
    const double slack = position_slack(
        largest_coordinate({ray.origin, plane.point, ray.origin + t * ray.direction}));
    const bool grazing = den <= 2.0 * kRelativeSlack * d_length * n_length;
    const double t_tolerance = 2.0 * slack * n_length / den + kRelativeSlack * std::abs(t);

    expected.hit = g.in_range;
    expected.near_boundary =
        grazing || possible(g.in_range, near_range_end(ray, t, t_tolerance)).ambiguous();
    if (!expected.hit && !expected.near_boundary) return expected;

    expected.t = t;
    expected.t_tolerance = t_tolerance;
    const Vec3 scaled = plane.normal / std::max({std::abs(plane.normal.x), std::abs(plane.normal.y),
                                                 std::abs(plane.normal.z)});
    expected.normal = scaled / glm::length(scaled);
    expected.normal_tolerance = 4.0 * kRelativeSlack;
    return expected;
}

}  // namespace raystep
