// Stage 3 reference solution: ray-sphere in the numerically stable form.

#include <cmath>
#include <utility>

#include "solutions/3_intersect/hit_building.h"
#include "solutions/3_intersect/single_precision.h"

namespace raystep {

namespace {

// a + b as an unevaluated sum hi + lo, exactly (Knuth's TwoSum).
template <class Real>
void add_exactly(Real a, Real b, Real& hi, Real& lo) {
    hi = a + b;
    const Real b_part = hi - a;
    lo = (a - (hi - b_part)) + (b - b_part);
}

// A sum of terms kept as a large part, summed exactly, and the small parts the exact sums shed,
// summed in plain arithmetic (Ogita, Rump, Oishi 2005, "Accurate sum and dot product").
template <class Real>
struct CompensatedSum {
    Real large = 0;
    Real small = 0;

    /// Adds large_term + small_term, large_term exactly.
    void add(Real large_term, Real small_term) {
        Real rounding;
        add_exactly(large, large_term, large, rounding);
        small += rounding + small_term;
    }
    /// Adds x * y, the product split exactly by a fused multiply-add.
    void add_product(Real x, Real y, Real small_term = 0) {
        const Real product = x * y;
        add(product, std::fma(x, y, -product) + small_term);
    }
    Real value() const { return large + small; }
};

// The ray's origin relative to the centre, A - C = hi + lo exactly, in units of s. A - C rounded
// is already off by an ulp of |A|: for an origin just outside a huge sphere that is most of the
// gap between them.
template <class Vector, class Real>
void exact_offset(const Vector& origin, const Vector& center, Real s, Vector& hi, Vector& lo) {
    for (int k = 0; k < 3; ++k) {
        add_exactly(origin[k], -center[k], hi[k], lo[k]);
        hi[k] /= s;
        lo[k] /= s;
    }
}

// With f = A - C and a unit direction d, |A + t d - C|^2 = r^2 is t^2 + 2 b t + c = 0 with
// b = d . f, c = f . f - r^2, roots -b -+ sqrt(b^2 - c). Three things go wrong in that form:
// - b^2 - c cancels catastrophically when the sphere is small and far (both terms ~ |f|^2, their
//   difference ~ r^2). Rewritten as r^2 - |f - (f . d) d|^2, r^2 minus the squared distance from
//   C to the ray's line, it has no such cancellation (Haines, Günther, Akenine-Möller, Ray
//   Tracing Gems ch. 7, 2019).
// - c = f . f - r^2 cancels when the origin is just outside a huge sphere (c ~ 2 r gap, far
//   below r^2), and so does b = d . f when the ray meets it at a grazing angle. Both are summed
//   from the exact offset with compensated products, to a few of their own ulps, so that the near
//   root c / q is too; b^2 - c is then the more accurate discriminant wherever b^2 + |c| is
//   below r |f|, and the distance form above elsewhere. docs/stage3.md, "How accurate the
//   reference is", has the bound.
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
    Vector hi, lo;
    exact_offset(ray.origin, sphere.center, s, hi, lo);
    const Vector f = offset / s;
    const Real r = sphere.radius / s;
    const Vector d = ray.direction / speed;

    // The quadratic's coefficients. Plain sums keep a few ulps of themselves unless they cancel
    // (b below half of |f|, c below half of |f|^2 + r^2); then they are summed again from the
    // exact offset, b = D . (hi + lo) / |D| and c = |hi + lo|^2 - r^2, the large products split
    // exactly. The second way costs three times the first, and only rays that need it pay.
    const Real f_squared = glm::dot(f, f);
    Real b = glm::dot(d, f);
    Real c = f_squared - r * r;
    if (!(2 * std::abs(b) >= std::sqrt(f_squared))) {
        CompensatedSum<Real> along;
        for (int k = 0; k < 3; ++k)
            along.add_product(ray.direction[k], hi[k], ray.direction[k] * lo[k]);
        b = along.value() / speed;
    }
    if (!(2 * std::abs(c) >= f_squared + r * r)) {
        CompensatedSum<Real> squares;
        for (int k = 0; k < 3; ++k)
            squares.add_product(hi[k], hi[k], (2 * hi[k] + lo[k]) * lo[k]);
        squares.add_product(-r, r);
        c = squares.value();
    }

    // The discriminant, in whichever form rounds less: b^2 - c, off by a few ulps of b^2 + |c|,
    // or r^2 minus the squared distance from C to the line, off by a few ulps of r |f| (f and d
    // round by an ulp of their size before the distance cancels). The first wins from just
    // outside a huge sphere, the second for a small sphere far away.
    Real discriminant = b * b - c;
    if (!(b * b + std::abs(c) <= 2 * r * std::sqrt(f_squared))) {
        const Vector to_line = f - b * d;
        discriminant = r * r - glm::dot(to_line, to_line);
    }
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
