// Stage 3: ray-sphere. Handout: docs/stage3.md, "Ray-sphere".

#include <cmath>
#include <utility>

#include "stages/1_vectors/vectors.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

namespace {

bool in_range(const Ray& ray, double t) {
    return t >= ray.t_min && t <= ray.t_max && std::isfinite(t);  // false for NaN
}

}  // namespace

std::optional<Hit> intersect_sphere(const Ray& ray, const Sphere& sphere) {
    if (!(sphere.radius > 0.0)) return std::nullopt;  // a zero radius is a miss

    // a t^2 + 2 b t + c = 0 with f = A - C
    const Vec3 f = ray.origin - sphere.center;
    const double a = dot(ray.direction, ray.direction);
    if (a == 0.0) return std::nullopt;  // a zero direction
    const double b = dot(ray.direction, f);
    const double c = dot(f, f) - sphere.radius * sphere.radius;

    // b^2 - a c as a (r^2 - |f - (b / a) D|^2): r^2 minus the squared distance from the centre
    // to the ray's line, which does not cancel for a small sphere far away.
    const Vec3 to_line = f - (b / a) * ray.direction;
    const double discriminant = a * (sphere.radius * sphere.radius - dot(to_line, to_line));
    if (!(discriminant >= 0.0)) return std::nullopt;

    // The stable form: q = -(b + sign(b) sqrt(b^2 - a c)), roots q / a and c / q. q = 0 only
    // when b = 0 and the discriminant is 0: a ray tangent at its own origin, one root t = 0.
    const double q = -(b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a;
    double t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);

    // The nearer root in range, else the farther one (the ray starts inside)
    const double t = in_range(ray, t0) ? t0 : t1;
    if (!in_range(ray, t)) return std::nullopt;

    // The outward normal (P - C) / |P - C|; a sphere too small to resolve at this distance can
    // put P on C itself, and has no normal there.
    const Vec3 outward = f + t * ray.direction;
    if (outward == Vec3(0.0)) return std::nullopt;
    return Hit{t, normalize(outward)};
}

}  // namespace raystep
