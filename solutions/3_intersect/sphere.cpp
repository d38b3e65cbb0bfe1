// Stage 3 reference solution: ray-sphere in the numerically stable form.

#include <cmath>
#include <utility>

#include "solutions/3_intersect/hit_building.h"
#include "solutions/3_intersect/single_precision.h"

namespace raystep {

namespace {

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
//
// Written once for double and float (hit_building.h).
template <class RayType, class SphereType, class Real = decltype(RayType::t_min)>
std::optional<Hit> stable_sphere(const RayType& ray, const SphereType& sphere) {
    using Vector = glm::vec<3, Real>;
    if (!(sphere.radius > 0)) return std::nullopt;
    const Real speed = glm::length(ray.direction);
    if (!(speed > 0)) return std::nullopt;

    // Scaled units: distances divided by s, the direction made unit
    const Vector offset = ray.origin - sphere.center;
    const Real size =
        std::max({std::abs(offset.x), std::abs(offset.y), std::abs(offset.z), sphere.radius});
    const Real s = std::ldexp(Real(1), std::ilogb(size));
    const Vector f = offset / s;
    const Real r = sphere.radius / s;
    const Vector d = ray.direction / speed;

    // The quadratic's coefficients and its discriminant
    const Real b = glm::dot(d, f);
    const Real c = glm::dot(f, f) - r * r;
    const Vector to_line = f - b * d;
    const Real discriminant = r * r - glm::dot(to_line, to_line);
    if (!(discriminant >= 0)) return std::nullopt;  // the line passes the sphere; rejects NaN

    // Both roots without cancellation. q = 0 only when the origin is on the sphere and the ray
    // is tangent there (b = 0, discriminant = 0, c = 0): one root, t = 0.
    const Real q = -(b + std::copysign(std::sqrt(discriminant), b));
    Real t0 = q;
    Real t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);

    // The nearer root in range, else the farther (the ray starts inside), back in ray units
    const Real to_ray_units = s / speed;
    const Real near = t0 * to_ray_units;
    const Real far = t1 * to_ray_units;
    const bool take_near = in_ray_range(ray, near);
    const Real t = take_near ? near : far;
    if (!in_ray_range(ray, t)) return std::nullopt;

    // The outward normal, from the scaled hit point relative to the centre; a sphere too small
    // to resolve at this distance leaves nothing to normalize, and counts as missed.
    const Vector outward = f + (take_near ? t0 : t1) * d;
    if (outward == Vector(0)) return std::nullopt;
    return Hit{t, Vec3(unit_vector(outward))};
}

}  // namespace

std::optional<Hit> intersect_sphere(const Ray& ray, const Sphere& sphere) {
    return stable_sphere(ray, sphere);
}

std::optional<Hit> intersect_sphere_float(const Ray& ray, const Sphere& sphere) {
    return stable_sphere(FloatRay(ray), FloatSphere(sphere));
}

}  // namespace raystep
