#include "grading/3_intersect/dyadic_hits.h"

#include <cmath>

namespace raystep {

// The bits these spend: vertices and points are multiples of 1/64 below 16 (10 bits), directions
// multiples of 1/8 below 4 and t a multiple of 1/4 below 8, so an origin is a multiple of 1/32
// below 48 (11 bits). A direction's largest component is a power of two, so the watertight test's
// shear (Woop, Benthin and Wald 2013), which divides by it, is exact too, and so is D . N, so that
// a test that multiplies by a reciprocal instead of dividing is exact as well. A triple product of
// differences of them, Cramer's determinant, needs under 40 bits, and a sphere's b^2 - a c under
// 50: inside a double's 53, so nothing rounds. A quotient of two exact numbers rounds once, to the
// exact t, which is itself such a multiple.

double dyadic(PortableRandom& random, double extent) {
    const auto steps = static_cast<std::int64_t>(8.0 * extent);
    return static_cast<double>(random.integer(-steps, steps)) / 8.0;
}

Vec3 dyadic_point(PortableRandom& random, double extent) {
    const double x = dyadic(random, extent);
    const double y = dyadic(random, extent);
    return {x, y, dyadic(random, extent)};
}

Ray dyadic_ray_to(PortableRandom& random, const Vec3& point, int axis, bool along_axis, double& t) {
    Vec3 direction(0.0);
    const double sign = random.unit() < 0.5 ? -1.0 : 1.0;
    direction[axis] = sign * std::ldexp(1.0, static_cast<int>(random.integer(0, 2)));
    if (!along_axis) {
        direction[(axis + 1) % 3] = dyadic(random, 1.0);
        direction[(axis + 2) % 3] = dyadic(random, 1.0);
    }
    t = static_cast<double>(random.integer(4, 32)) / 4.0;
    return Ray{point - t * direction, direction};
}

Triangle dyadic_triangle_around(PortableRandom& random, const Vec3& point, int axis) {
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    // Two edges in the plane, drawn again until their cross product is a power of two from 1/2
    // to 32 (about one draw in a hundred): then D . N, which every test divides by or takes the
    // reciprocal of, is a power of two, and a reciprocal 1 / det (Moller and Trumbore write
    // t = (e2 . q) * (1 / det)) is exact like the quotient
    Vec3 e1(0.0);
    Vec3 e2(0.0);
    const auto power_of_two = [](double x) {
        int exponent = 0;
        return std::frexp(std::abs(x), &exponent) == 0.5 && std::abs(x) >= 0.5 &&
               std::abs(x) <= 32.0;
    };
    do {
        e1[u] = dyadic(random, 4.0);
        e1[v] = dyadic(random, 4.0);
        e2[u] = dyadic(random, 4.0);
        e2[v] = dyadic(random, 4.0);
    } while (!power_of_two(e1[u] * e2[v] - e1[v] * e2[u]));

    // Barycentrics in eighths, none below 1/8: the point is well inside
    const auto beta_eighths = random.integer(1, 6);
    const double beta = static_cast<double>(beta_eighths) / 8.0;
    const double gamma = static_cast<double>(random.integer(1, 7 - beta_eighths)) / 8.0;
    const Vec3 p0 = point - beta * e1 - gamma * e2;
    if (random.unit() < 0.5) return Triangle{p0, p0 + e1, p0 + e2};
    return Triangle{p0, p0 + e2, p0 + e1};
}

Plane dyadic_plane_through(PortableRandom& random, const Vec3& point, int axis) {
    Vec3 normal(0.0);
    normal[axis] = (random.unit() < 0.5 ? -1.0 : 1.0) *
                   std::ldexp(1.0, static_cast<int>(random.integer(-2, 2)));
    Vec3 on_plane = point;
    on_plane[(axis + 1) % 3] += dyadic(random, 2.0);
    on_plane[(axis + 2) % 3] += dyadic(random, 2.0);
    return Plane{on_plane, normal};
}

Sphere dyadic_sphere_entered_at(PortableRandom& random, const Vec3& point, int axis, double sign,
                                double& chord) {
    const double s = std::ldexp(1.0, static_cast<int>(random.integer(-2, 1)));
    Vec3 centre = point;
    if (random.unit() < 0.5) {
        centre[axis] += sign * s;
        chord = 2.0 * s;
        return Sphere{centre, s};
    }
    const int aside = (axis + static_cast<int>(random.integer(1, 2))) % 3;
    centre[axis] += sign * 4.0 * s;
    centre[aside] += (random.unit() < 0.5 ? -3.0 : 3.0) * s;
    chord = 8.0 * s;
    return Sphere{centre, 5.0 * s};
}

}  // namespace raystep
