#include "grading/3_intersect/collinear_triangles.h"

#include <cmath>

#include "grading/3_intersect/dyadic_hits.h"

namespace raystep {

namespace {

// How many triangles and rays to draw before giving up on tripping the form: far more than it
// takes (the grader's tests draw one case for each of 100 seeds and each form, and every one
// trips).
constexpr int kMostDraws = 4096;

// The arithmetic of stage 1's dot and cross as the reference and the handout write them, in this
// order, so that a form's rounding here is a student's (the grader compiles with
// -ffp-contract=off, as it compiles the probe).
double dot3(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

Vec3 cross3(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

double det(const Vec3& a, const Vec3& b, const Vec3& c) {
    return dot3(a, cross3(b, c));
}

bool in_range(const Ray& ray, double t) {
    return t >= ray.t_min && t <= ray.t_max && std::isfinite(t);
}

// docs/stage3.md, "Method 3: Cramer's rule": beta (p0 - p1) + gamma (p0 - p2) + t D = p0 - A
bool cramer_hits(const Ray& ray, const Triangle& tri) {
    const Vec3 c0 = tri.p0 - tri.p1;
    const Vec3 c1 = tri.p0 - tri.p2;
    const Vec3 rhs = tri.p0 - ray.origin;
    const double m = det(c0, c1, ray.direction);
    if (m == 0.0) return false;
    const double t = det(c0, c1, rhs) / m;
    const double gamma = det(c0, rhs, ray.direction) / m;
    const double beta = det(rhs, c1, ray.direction) / m;
    return in_range(ray, t) && gamma >= 0.0 && gamma <= 1.0 && beta >= 0.0 && beta <= 1.0 - gamma;
}

// Moller and Trumbore, "Fast, minimum storage ray-triangle intersection", JGT 2(1), 1997
bool moller_trumbore_hits(const Ray& ray, const Triangle& tri) {
    const Vec3 e1 = tri.p1 - tri.p0;
    const Vec3 e2 = tri.p2 - tri.p0;
    const Vec3 p = cross3(ray.direction, e2);
    const double d = dot3(e1, p);
    if (d == 0.0) return false;
    const Vec3 s = ray.origin - tri.p0;
    const double beta = dot3(s, p) / d;
    const Vec3 q = cross3(s, e1);
    const double gamma = dot3(ray.direction, q) / d;
    const double t = dot3(e2, q) / d;
    return in_range(ray, t) && beta >= 0.0 && beta <= 1.0 && gamma >= 0.0 && beta + gamma <= 1.0;
}

// Three points on one line, p0 + a_k s with a_0 = 0, a_1 and a_2 multiples of 1/4 in [-2, 2] and s
// a multiple of 1/8: every coordinate a multiple of 1/32, so the differences and their cross
// products are exact and the normal is exactly zero. Two of the a_k may be equal (a repeated
// vertex).
struct Line {
    Triangle triangle;
    Vec3 base;
    Vec3 step;
    double low;   ///< the smallest a_k
    double high;  ///< the largest
};

Line collinear_triangle(PortableRandom& random) {
    Line line;
    line.base = dyadic_point(random, 4.0);
    line.step = Vec3(0.0);
    while (line.step == Vec3(0.0))
        line.step = dyadic_point(random, 2.0);
    const double a1 = static_cast<double>(random.integer(-8, 8)) / 4.0;
    const double a2 = static_cast<double>(random.integer(-8, 8)) / 4.0;
    line.low = std::fmin(0.0, std::fmin(a1, a2));
    line.high = std::fmax(0.0, std::fmax(a1, a2));
    line.triangle = Triangle{line.base, line.base + a1 * line.step, line.base + a2 * line.step};
    return line;
}

}  // namespace

bool form_reports_hit(SolveForm form, const Ray& ray, const Triangle& triangle) {
    return form == SolveForm::cramer ? cramer_hits(ray, triangle)
                                     : moller_trumbore_hits(ray, triangle);
}

CollinearCase collinear_case(PortableRandom& random, SolveForm form) {
    CollinearCase drawn;
    for (int draw = 0; draw < kMostDraws && !drawn.trips; ++draw) {
        // A ray from 2 to 8 away, aimed at a point of the segment the three vertices span
        const Line line = collinear_triangle(random);
        const Vec3 target = line.base + random.uniform(line.low, line.high) * line.step;
        const Vec3 origin = target + random.unit_vector() * random.uniform(2.0, 8.0);
        drawn.triangle = line.triangle;
        drawn.ray = Ray{origin, (target - origin) * random.decade(-1.0, 1.0)};
        drawn.trips = form_reports_hit(form, drawn.ray, drawn.triangle);
    }
    return drawn;
}

}  // namespace raystep
