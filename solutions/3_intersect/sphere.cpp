// Stage 3 reference solution: ray-sphere in the numerically stable form.

#include <cmath>
#include <utility>

#include "solutions/3_intersect/triangle_hit.h"

namespace raystep {

// With f = A - C, |A + t D - C|^2 = r^2 is a t^2 + 2 b t + c = 0 with a = D . D, b = D . f,
// c = f . f - r^2, roots (-b -+ sqrt(b^2 - a c)) / a. Two things go wrong in that form:
// - b^2 - a c cancels catastrophically when the sphere is small and far (both terms ~ |f|^4,
//   their difference ~ r^2 |f|^2). Rewritten as a (r^2 - |f - (f . d^) d^|^2), it is r^2 minus
//   the squared distance from C to the ray's line, computed without cancellation (Haines,
//   Günther, Akenine-Möller, Ray Tracing Gems ch. 7, 2019).
// - -b + sqrt(...) cancels for the near root when b^2 >> a c. With q = -(b + sign(b) sqrt(...))
//   the roots are q / a and c / q, and neither subtracts nearly equal numbers.
std::optional<Hit> intersect_sphere(const Ray& ray, const Sphere& sphere) {
    const double r = sphere.radius;
    if (!(r > 0.0)) return std::nullopt;
    const double a = glm::dot(ray.direction, ray.direction);
    if (a == 0.0) return std::nullopt;

    // The quadratic's coefficients and its discriminant
    const Vec3 f = ray.origin - sphere.center;
    const double b = glm::dot(ray.direction, f);
    const double c = glm::dot(f, f) - r * r;
    const Vec3 unit = ray.direction / std::sqrt(a);
    const Vec3 to_line = f - glm::dot(f, unit) * unit;
    const double discriminant = a * (r * r - glm::dot(to_line, to_line));
    if (!(discriminant >= 0.0)) return std::nullopt;  // the line passes the sphere; rejects NaN

    // Both roots without cancellation. q = 0 only when the origin is on the sphere and the ray
    // is tangent there (b = 0, discriminant = 0, c = 0): one root, t = 0.
    const double q = -(b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a;
    double t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);

    // The nearer root in range, else the farther (the ray starts inside)
    const double t = in_ray_range(ray, t0) ? t0 : t1;
    if (!in_ray_range(ray, t)) return std::nullopt;
    const Vec3 p = ray.origin + t * ray.direction;
    return Hit{t, glm::normalize(p - sphere.center)};
}

}  // namespace raystep
