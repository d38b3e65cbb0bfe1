#include <glm/geometric.hpp>

#include "grading/3_intersect/exact_hits.h"
#include "grading/3_intersect/exact_intersection.h"
#include "grading/3_intersect/possible_answers.h"
#include "grading/3_intersect/rounding_budget.h"

namespace raystep {

namespace {

// The exact geometry of a ray and a triangle.
struct TriangleGeometry {
    bool degenerate = true;  ///< a zero direction or a degenerate (collinear) triangle
    bool parallel = false;   ///< the ray is parallel to the triangle's plane
    exact::Number u, v, w;   ///< signed volumes of the ray's line with edges p1p2, p2p0, p0p1
    exact::Number den;       ///< u + v + w = D . N
    exact::Number t;
    exact::Vector normal;  ///< (p1 - p0) x (p2 - p0), exact
    CGAL::Sign signs[3] = {CGAL::ZERO, CGAL::ZERO, CGAL::ZERO};
    bool inside = false;    ///< the line meets the closed triangle
    bool in_range = false;  ///< t is in [t_min, t_max]
};

TriangleGeometry solve_triangle(const Ray& ray, const Triangle& tri) {
    using namespace exact;
    TriangleGeometry g;
    const Point p0 = point(tri.p0);
    const Point p1 = point(tri.p1);
    const Point p2 = point(tri.p2);
    if (ray.direction == Vec3(0.0) || CGAL::collinear(p0, p1, p2)) return g;
    g.degenerate = false;
    const Point origin = point(ray.origin);
    const Vector d = vector(ray.direction);
    const Vector a0 = p0 - origin;
    const Vector a1 = p1 - origin;
    const Vector a2 = p2 - origin;

    // The signed volumes of the ray's line with each edge are the barycentric weights of the
    // point where the line meets the plane, scaled by their sum D . N (Plücker coordinates).
    g.u = d * CGAL::cross_product(a1, a2);  // the weight of p0
    g.v = d * CGAL::cross_product(a2, a0);  // the weight of p1
    g.w = d * CGAL::cross_product(a0, a1);  // the weight of p2
    g.den = g.u + g.v + g.w;
    g.signs[0] = CGAL::sign(g.u);
    g.signs[1] = CGAL::sign(g.v);
    g.signs[2] = CGAL::sign(g.w);
    if (CGAL::is_zero(g.den)) {
        g.parallel = true;
        return g;
    }

    g.normal = CGAL::cross_product(p1 - p0, p2 - p0);
    g.t = (a0 * g.normal) / g.den;
    const bool positive = g.signs[0] == CGAL::POSITIVE || g.signs[1] == CGAL::POSITIVE ||
                          g.signs[2] == CGAL::POSITIVE;
    const bool negative = g.signs[0] == CGAL::NEGATIVE || g.signs[1] == CGAL::NEGATIVE ||
                          g.signs[2] == CGAL::NEGATIVE;
    g.inside = !(positive && negative);
    g.in_range = g.t >= ray.t_min && (!std::isfinite(ray.t_max) || g.t <= ray.t_max);
    return g;
}

// Which answers rounding allows for "inside": an edge whose signed volume is within its slack
// may be taken as either sign.
PossibleAnswers possibly_inside(const CGAL::Sign signs[3], const bool within_slack[3]) {
    bool positive = false;
    bool negative = false;
    int free_edges = 0;
    for (int k = 0; k < 3; ++k) {
        if (within_slack[k]) {
            ++free_edges;
        } else {
            positive = positive || signs[k] == CGAL::POSITIVE;
            negative = negative || signs[k] == CGAL::NEGATIVE;
        }
    }
    // Inside when no two edges disagree. Outside when two fixed edges disagree, or a free edge can
    // take the sign opposite to a fixed one, or two free edges can take opposite signs.
    const bool can_be_inside = !(positive && negative);
    const bool can_be_outside =
        (positive && negative) || (free_edges >= 1 && (positive || negative)) || free_edges >= 2;
    return {can_be_inside, can_be_outside};
}

// The exact normal's direction and length, rounded. Its double cross product can round to
// zero, or to a vector pointing anywhere, on a sliver whose edges are nearly parallel (their
// products cancel), though the exact normal is not zero: scaling the exact normal by its largest
// component is exact, rounding the scaled components costs half an ulp each, and normalizing
// that vector of length 1 to sqrt(3) costs a few more.
struct RoundedNormal {
    Vec3 unit;
    double length;
};

RoundedNormal rounded_normal(const exact::Vector& n) {
    const exact::Number components[3] = {n.x(), n.y(), n.z()};
    int largest = 0;
    for (int k = 1; k < 3; ++k) {
        if (CGAL::abs(components[k]) > CGAL::abs(components[largest])) largest = k;
    }
    const exact::Number size = CGAL::abs(components[largest]);
    const Vec3 scaled{exact::rounded(components[0] / size), exact::rounded(components[1] / size),
                      exact::rounded(components[2] / size)};
    const double scaled_length = glm::length(scaled);
    return {scaled / scaled_length, exact::rounded(size) * scaled_length};
}

}  // namespace

std::optional<exact::HitTime> exact::triangle_hit_time(const Ray& ray, const Triangle& triangle) {
    const TriangleGeometry g = solve_triangle(ray, triangle);
    if (g.degenerate || g.parallel || !g.inside || !g.in_range) return std::nullopt;
    HitTime time;
    time.rational = g.t;
    return time;
}

Expectation expect_triangle(const Ray& ray, const Triangle& tri) {
    Expectation expected;  // a miss, away from any boundary, until shown otherwise
    const TriangleGeometry g = solve_triangle(ray, tri);
    // Degenerate input is a miss by the contract, whatever rounding might suggest. A ray parallel
    // to the plane is one too, but turned by a rounding it would cross the plane.
    if (g.degenerate) return expected;
    if (g.parallel) {
        expected.near_boundary = true;
        return expected;
    }

    // Sizes for the budget, in doubles: they only set tolerances. The normal's length comes
    // from the exact normal: a sliver's double cross product can round to zero.
    const Vec3 e1 = tri.p1 - tri.p0;
    const Vec3 e2 = tri.p2 - tri.p0;
    const RoundedNormal n = rounded_normal(g.normal);
    const double n_length = n.length;
    const double d_length = glm::length(ray.direction);
    const double den = std::abs(exact::approximate(g.den));
    const double t = exact::rounded(g.t);
    const double slack = position_slack(
        largest_coordinate({ray.origin, tri.p0, tri.p1, tri.p2, ray.origin + t * ray.direction}));

    // Nearly parallel: D . N within what moving the vertices and turning D can change.
    const bool grazing = den <= d_length * (2.0 * slack * (glm::length(e1) + glm::length(e2)) +
                                            kRelativeSlack * n_length);

    // t moves by the slack over the cosine of the angle of incidence (|D . N| / |D| |N|); by the
    // plane's tilt (moving the vertices turns a sliver's plane a long way) times the hit point's
    // distance from the pivot, which may be any vertex, over the same cosine; and by the
    // direction's own slack.
    const double tilt = 2.0 * slack * (glm::length(e1) + glm::length(e2)) / n_length;
    const Vec3 point = ray.origin + t * ray.direction;
    const double lever = std::max(
        {glm::length(point - tri.p0), glm::length(point - tri.p1), glm::length(point - tri.p2)});
    const double t_tolerance =
        (slack + tilt * lever) * n_length / den + kRelativeSlack * std::abs(t);

    // Inside: each edge's side, with the edges within their slack free to go either way. Moving
    // the two vertices by the slack and turning D changes the signed volume D . (a x b) by at
    // most this.
    const auto side_slack = [&](const Vec3& p, const Vec3& q) {
        const double a = glm::length(p - ray.origin);
        const double b = glm::length(q - ray.origin);
        return d_length * (slack * (a + b) + kRelativeSlack * a * b);
    };
    const bool within_slack[3] = {std::abs(exact::approximate(g.u)) <= side_slack(tri.p1, tri.p2),
                                  std::abs(exact::approximate(g.v)) <= side_slack(tri.p2, tri.p0),
                                  std::abs(exact::approximate(g.w)) <= side_slack(tri.p0, tri.p1)};
    const PossibleAnswers inside = possibly_inside(g.signs, within_slack);
    const PossibleAnswers in_range = possible(g.in_range, near_range_end(ray, t, t_tolerance));

    expected.hit = g.inside && g.in_range;
    expected.near_boundary = grazing || both(inside, in_range).ambiguous();
    if (!expected.hit && !expected.near_boundary) return expected;

    // Where the ray meets the plane: t, the normal and the barycentrics, with their tolerances.
    // A barycentric moves by a position's error over the triangle's smallest altitude.
    const double longest_edge =
        std::max({glm::length(e1), glm::length(e2), glm::length(tri.p2 - tri.p1)});
    const double smallest_altitude = n_length / longest_edge;
    expected.t = t;
    expected.t_tolerance = t_tolerance;
    expected.normal = n.unit;
    expected.normal_tolerance = tilt + kRelativeSlack;
    expected.beta = exact::rounded(g.v / g.den);
    expected.gamma = exact::rounded(g.w / g.den);
    expected.barycentric_tolerance =
        (slack + t_tolerance * d_length) / smallest_altitude + kRelativeSlack;
    return expected;
}

}  // namespace raystep
