// Stage 3 reference solution: ray-sphere in the numerically stable form.

#include <cmath>
#include <utility>

#include "solutions/3_intersect/hit_building.h"

namespace raystep {

// With f = A - C and a unit direction d, |A + t d - C|^2 = r^2 is t^2 + 2 b t + c = 0 with
// b = d . f, c = f . f - r^2, roots -b -+ sqrt(b^2 - c). Three things go wrong in that form:
// - b^2 - c cancels catastrophically when the sphere is small and far (both terms ~ |f|^2, their
//   difference ~ r^2). Rewritten as r^2 - |f - (f . d) d|^2, r^2 minus the squared distance from
//   C to the ray's line, it has no such cancellation (Haines, Günther, Akenine-Möller, Ray
//   Tracing Gems ch. 7, 2019).
// - -b + sqrt(...) cancels for the near root when b^2 >> |c|. With q = -(b + sign(b) sqrt(...)),
//   the roots are q and c / q, and neither subtracts nearly equal numbers.
// - Squares overflow for lengths above 1e154 and underflow below 1e-154. Everything is measured
//   in units of s, a power of two near the larger of |f| and r: dividing by s is exact, and the
//   scaled lengths are near 1.
std::optional<Hit> intersect_sphere(const Ray& ray, const Sphere& sphere) {
    if (!(sphere.radius > 0.0)) return std::nullopt;
    const double speed = glm::length(ray.direction);
    if (!(speed > 0.0)) return std::nullopt;

    // Scaled units: distances divided by s, the direction made unit
    const Vec3 offset = ray.origin - sphere.center;
    const double size =
        std::max({std::abs(offset.x), std::abs(offset.y), std::abs(offset.z), sphere.radius});
    const double s = std::ldexp(1.0, std::ilogb(size));
    const Vec3 f = offset / s;
    const double r = sphere.radius / s;
    const Vec3 d = ray.direction / speed;

    // The quadratic's coefficients and its discriminant
    const double b = glm::dot(d, f);
    const double c = glm::dot(f, f) - r * r;
    const Vec3 to_line = f - b * d;
    const double discriminant = r * r - glm::dot(to_line, to_line);
    if (!(discriminant >= 0.0)) return std::nullopt;  // the line passes the sphere; rejects NaN

    // Both roots without cancellation. q = 0 only when the origin is on the sphere and the ray
    // is tangent there (b = 0, discriminant = 0, c = 0): one root, t = 0.
    const double q = -(b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q;
    double t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);

    // The nearer root in range, else the farther (the ray starts inside), back in ray units
    const double to_ray_units = s / speed;
    const double near = t0 * to_ray_units;
    const double far = t1 * to_ray_units;
    const bool take_near = in_ray_range(ray, near);
    const double t = take_near ? near : far;
    if (!in_ray_range(ray, t)) return std::nullopt;

    // The outward normal, from the scaled hit point relative to the centre; a sphere too small
    // to resolve at this distance leaves nothing to normalize, and counts as missed.
    const Vec3 outward = f + (take_near ? t0 : t1) * d;
    if (outward == Vec3(0.0)) return std::nullopt;
    return Hit{t, unit_vector(outward)};
}

}  // namespace raystep
