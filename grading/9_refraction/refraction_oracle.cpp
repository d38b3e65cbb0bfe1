#include "grading/9_refraction/refraction_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "grading/7_recursion/recursion_oracle.h"

namespace raystep {

namespace {

using grade::ExpectedRay;

constexpr Wide kU = kWideUnitRoundoff;  // a double's unit roundoff, 2^-53
constexpr Wide kOwnU = 0x1p-64L;        // the oracle's own, a long double's

// --- The rounding budget of cos(theta2)
//
// A right formula in double, with unit inputs rounded to doubles (each within 2u of length 1),
// computes cos1 within 8u (a dot product, 3u, and both lengths), 1 - cos1^2 within 18u, and
// q = cos2^2 = 1 - eta^2 (1 - cos1^2) within (21 eta^2 + 1) u, budgeted as (24 eta^2 + 2) u. Its
// square root then errs by at most min(sqrt(e), e / cos2) + u: the root of an error near the
// critical angle (cos2 near 0, where Snell's direction turns fast), e / (2 cos2) away from it.
// Trigonometric forms (asin of eta sin(theta1)) stay within the same: asin's conditioning
// 1 / cos2 times (eta + 2) u.

Wide cos2_squared_budget(Wide eta, Wide u) {
    return (24 * eta * eta + 2) * u;
}

Wide root_error(Wide root, Wide squared_error, Wide u) {
    const Wide near_zero = std::sqrt(squared_error);
    return (root > 0 ? std::min(near_zero, squared_error / root) : near_zero) + u;
}

WideVec normalized(const Vec3& v) {
    return glm::normalize(widen(v));
}

// --- Fresnel in long double, from both cosines

Wide fresnel_from_cosines(Wide cos1, Wide cos2, Wide n1, Wide n2) {
    if (cos2 <= 0) return 1;  // at or beyond the critical angle
    const Wide r_s = (n1 * cos1 - n2 * cos2) / (n1 * cos1 + n2 * cos2);
    const Wide r_p = (n2 * cos1 - n1 * cos2) / (n2 * cos1 + n1 * cos2);
    return (r_s * r_s + r_p * r_p) / 2;
}

Wide schlick_from_cosine(Wide cos, Wide n1, Wide n2) {
    if (cos <= 0) return 1;
    const Wide r0 = (n1 - n2) / (n1 + n2);
    const Wide m = 1 - cos;
    return r0 * r0 + (1 - r0 * r0) * m * m * m * m * m;
}

// The far side's cosine for an input cosine, its square q (negative beyond the critical angle)
// and q's rounding budget in double.
struct FarCosine {
    Wide q = 0;
    Wide budget = 0;
    Wide low = 0;   // the least cos2 a right formula may compute
    Wide high = 0;  // the greatest
};

// cos_incident is exact, so q = 1 - eta^2 (1 - c^2) errs by (8 eta^2 + 4) u in double: 1 - c^2
// within 2u, the product and the square within 3 roundings each.
FarCosine far_cosine(Wide cos1, Wide n1, Wide n2) {
    const Wide eta = n1 / n2;
    FarCosine f;
    f.q = 1 - eta * eta * (1 - cos1 * cos1);
    f.budget = (8 * eta * eta + 4) * kU;
    f.low = std::max<Wide>(0, std::sqrt(std::max<Wide>(0, f.q - f.budget)) - 2 * kU);
    f.high = std::sqrt(std::max<Wide>(0, f.q + f.budget)) + 2 * kU;
    return f;
}

// The largest change of `f` over the corners of the cosines' rounding box, plus 16u for the
// quotients' own rounding (each reflectance r = (a - b) / (a + b) of positive a and b errs by
// 2u at most, its square by 4u).
template <typename F>
Wide corner_spread(const F& f, Wide value, Wide c1_low, Wide c1_high, Wide c2_low, Wide c2_high) {
    Wide spread = 0;
    for (const Wide c1 : {c1_low, c1_high}) {
        for (const Wide c2 : {c2_low, c2_high})
            spread = std::max(spread, std::abs(f(c1, c2) - value));
    }
    return spread + 16 * kU;
}

// --- The sine-and-tangent form's rounding budget
//
// Fresnel's equations in angles, r_s = -sin(theta1 - theta2) / sin(theta1 + theta2) and
// r_p = tan(theta1 - theta2) / tan(theta1 + theta2), equal the cosine form only on Snell's law,
// and a right formula in double leaves it where it takes the two angles by different roads:
// theta1 = acos(c) is right to an ulp, while sin(theta1) = sqrt(1 - c^2), from which Snell's law
// gives theta2, carries the rounding of c^2. Near head-on that is a relative error up to 2^-28 in
// sin^2(theta1) (c = 1 - e rounds c^2 by at most min(u / 2, e^2)), and the ratio theta2 / theta1,
// all the form sees there, moves with it. Taken the other road, theta1 = asin(sqrt(1 - c^2)) near
// grazing moves by the rounding of 1 - c^2 over cos(theta1). So the budget is the form's spread
// over the box of both angles: theta1 by either road, theta2 = asin(eta sin(theta1)), each library
// call and product within 2u, plus the quotients' 16u as in the cosine form.

Wide fresnel_from_angles(Wide theta1, Wide theta2, Wide n1, Wide n2) {
    const Wide sum = theta1 + theta2;
    if (!(sum > 0)) {  // head-on: the limit, ((n1 - n2) / (n1 + n2))^2
        const Wide r0 = (n1 - n2) / (n1 + n2);
        return r0 * r0;
    }
    const Wide r_s = std::sin(theta1 - theta2) / std::sin(sum);
    const Wide r_p = std::tan(theta1 - theta2) / std::tan(sum);
    return (r_s * r_s + r_p * r_p) / 2;
}

Wide angle_form_spread(Wide value, double cos_incident, Wide n1, Wide n2) {
    const Wide c = std::clamp<Wide>(cos_incident, 0, 1);
    const Wide half_pi = kWidePi / 2;
    // sin(theta1) = sqrt(1 - c^2) as a double formula has it
    const Wide q = 1 - c * c;
    const Wide q_error = std::min(kU / 2, (1 - c) * (1 - c)) + kU * q;
    const Wide sin1_low = std::sqrt(std::max<Wide>(0, q - q_error)) * (1 - kU);
    const Wide sin1_high = std::min<Wide>(1, std::sqrt(q + q_error) * (1 + kU));
    // theta1 by acos(c) or by asin(sin(theta1))
    const Wide by_acos = std::acos(c);
    const Wide theta1_low = std::min(by_acos, std::asin(sin1_low)) * (1 - 2 * kU);
    const Wide theta1_high =
        std::min(half_pi, std::max(by_acos, std::asin(sin1_high)) * (1 + 2 * kU));
    // theta2 by Snell's law from that sine; beyond 1 there is no theta2, and F is 1
    const Wide eta = n1 / n2;
    const Wide sin2_low = eta * sin1_low * (1 - 2 * kU);
    const Wide sin2_high = eta * sin1_high * (1 + 2 * kU);
    if (sin2_low >= 1) return 16 * kU;
    const Wide theta2_low = std::asin(sin2_low) * (1 - 2 * kU);
    const Wide theta2_high =
        std::min(half_pi, std::asin(std::min<Wide>(1, sin2_high)) * (1 + 2 * kU));
    Wide spread = 0;
    for (const Wide theta1 : {theta1_low, theta1_high}) {
        for (const Wide theta2 : {theta2_low, theta2_high})
            spread =
                std::max(spread, std::abs(fresnel_from_angles(theta1, theta2, n1, n2) - value));
    }
    return spread + 16 * kU;
}

// Where the probe's fake scene looks for a ray's hit: the expected origin (the surface point
// under the error-bound rule, whose origin is a region a few ulps wide) and direction.
Ray key_of(const ExpectedRay& e, const Vec3& point) {
    const Vec3 origin = e.region ? point : narrow(e.origin);
    return {origin, narrow(e.direction), e.t_min, e.t_max};
}

}  // namespace

ExpectedRefraction expected_refraction(const Vec3& incident, const Vec3& normal, double eta) {
    const WideVec d = normalized(incident);
    const WideVec n = normalized(normal);
    const Wide w_eta = eta;
    const Wide cos1 = -glm::dot(d, n);
    const Wide q = 1 - w_eta * w_eta * (1 - cos1 * cos1);
    const Wide budget = cos2_squared_budget(w_eta, kU);
    ExpectedRefraction e;
    // Within twice the budget of q = 0 a right formula may answer either way.
    if (q < -2 * budget) {
        e.answer = RefractionAnswer::none;
        return e;
    }
    if (q <= 2 * budget) e.answer = RefractionAnswer::either;
    const Wide cos2 = std::sqrt(std::max<Wide>(0, q));
    e.direction = glm::normalize(w_eta * d + (w_eta * cos1 - cos2) * n);
    // In the band the computed q may reach 3 budgets, its root sqrt(3 budget).
    const Wide cos2_error = e.answer == RefractionAnswer::either ? std::sqrt(3 * budget) + kU
                                                                 : root_error(cos2, budget, kU);
    const Wide own_error = root_error(cos2, cos2_squared_budget(w_eta, kOwnU), kOwnU);
    e.tolerance = 4 * ((13 * w_eta + 6) * kU + cos2_error) + own_error;
    return e;
}

ExpectedNumber expected_fresnel_exact(double cos_incident, double n1, double n2) {
    const Wide c1 = cos_incident;
    const FarCosine far = far_cosine(c1, n1, n2);
    const auto fresnel = [&](Wide a, Wide b) { return fresnel_from_cosines(a, b, n1, n2); };
    ExpectedNumber e;
    e.value = far.q <= 0 ? 1 : fresnel(c1, std::sqrt(far.q));
    // Every right form's budget: the cosine form's and the sine-and-tangent form's.
    e.tolerance = std::max(
        corner_spread(fresnel, e.value, c1 * (1 - 4 * kU), c1 * (1 + 4 * kU), far.low, far.high),
        angle_form_spread(e.value, cos_incident, n1, n2));
    return e;
}

ExpectedNumber expected_fresnel_schlick(double cos_incident, double n1, double n2) {
    const Wide c1 = cos_incident;
    const auto schlick = [&](Wide, Wide c) { return schlick_from_cosine(c, n1, n2); };
    ExpectedNumber e;
    if (n1 <= n2) {
        e.value = schlick(0, c1);
        e.tolerance = corner_spread(schlick, e.value, 0, 0, c1 * (1 - 4 * kU), c1 * (1 + 4 * kU));
        return e;
    }
    // Leaving the denser medium: Schlick's cosine is cos(theta2), on the less dense side.
    const FarCosine far = far_cosine(c1, n1, n2);
    e.value = far.q <= 0 ? 1 : schlick(0, std::sqrt(far.q));
    e.tolerance = corner_spread(schlick, e.value, 0, 0, far.low, far.high);
    return e;
}

ExpectedRefractedRay expected_refracted_ray(const SurfacePoint& point, double n1, double n2,
                                            const RayOffset& offset) {
    const ExpectedRefraction r = expected_refraction(-point.to_eye, point.shading_normal, n1 / n2);
    ExpectedRefractedRay e;
    e.answer = r.answer;
    if (r.answer != RefractionAnswer::none)
        e.ray = expected_leaving_ray(point, r.direction, r.tolerance, offset);
    return e;
}

double expected_current_index(const MediumStack& inside) {
    return inside.empty() ? 1.0 : inside.back().index;
}

MediumStack expected_after_crossing(const MediumStack& inside, const Medium& solid, bool entering) {
    MediumStack after = inside;
    if (entering) {
        after.push_back(solid);
        return after;
    }
    for (std::size_t k = after.size(); k-- > 0;) {
        if (after[k].solid == solid.solid) {
            after.erase(after.begin() + static_cast<std::ptrdiff_t>(k));
            break;
        }
    }
    return after;
}

ExpectedRefractionRadiance expected_radiance_with_refraction(const HitMaker& make, const Ray& eye,
                                                             int bounces, const MediumStack& inside,
                                                             bool schlick,
                                                             const RayOffset& offset) {
    ExpectedRefractionRadiance e;
    // Each term of the colour is a local colour times a product of weights, all non-negative.
    // A weight's error grows by its factor's rounding (4u) and, for a Fresnel factor, by Kt
    // times F's tolerance; the sum of n terms rounds by n u of the terms' sum.
    WideVec terms(0);
    int traced = 0;
    const std::function<void(const ExpectedRay&, const Ray&, const MediumStack&, int,
                             const WideVec&, const WideVec&)>
        trace = [&](const ExpectedRay& expected, const Ray& key, const MediumStack& media, int left,
                    const WideVec& weight, const WideVec& weight_error) {
            e.rays.push_back(expected);
            ++traced;
            const std::optional<MediumHit> hit = make(key, media);
            if (!hit) return;
            e.scene.push_back({key, *hit});
            const ShadedHit& shaded = hit->shaded;
            const WideVec local = glm::abs(widen(shaded.local));
            e.colour += weight * widen(shaded.local);
            e.colour_tolerance += weight_error * local;
            terms += weight * local;
            if (left <= 0) return;

            const WideVec kt = widen(hit->transmission);
            const WideVec ks = widen(shaded.reflectance);
            ExpectedNumber fresnel;
            ExpectedRefractedRay through{RefractionAnswer::none, {}};
            MediumStack beyond;
            if (hit->transmission != Color(0.0)) {
                beyond = expected_after_crossing(media, hit->solid, hit->entering);
                const double n1 = expected_current_index(media);
                const double n2 = expected_current_index(beyond);
                const double cos1 = static_cast<double>(
                    glm::dot(widen(shaded.point.to_eye), widen(shaded.point.shading_normal)));
                through = expected_refracted_ray(shaded.point, n1, n2, offset);
                if (through.answer == RefractionAnswer::either) {
                    throw std::logic_error(
                        "a fake scene's hit within rounding of the critical angle");
                }
                // cos1 is a dot product the student rounds too: 8u more either way.
                const double low = std::max(0.0, cos1 * (1 - 8 * 0x1p-53));
                const double high = std::min(1.0, cos1 * (1 + 8 * 0x1p-53));
                const auto f = [&](double c) {
                    return schlick ? expected_fresnel_schlick(c, n1, n2)
                                   : expected_fresnel_exact(c, n1, n2);
                };
                fresnel = f(cos1);
                fresnel.tolerance += std::max(std::abs(f(low).value - fresnel.value),
                                              std::abs(f(high).value - fresnel.value));
                if (through.answer == RefractionAnswer::none) fresnel = {1, 0};
                if (shaded.reflectance == Color(0.0) && fresnel.value - fresnel.tolerance <= 0) {
                    throw std::logic_error(
                        "a fake scene's black mirror with F within rounding of 0");
                }
            }

            const WideVec reflect_weight = ks + kt * fresnel.value;
            if (reflect_weight != WideVec(0)) {
                const WideVec error = weight_error * reflect_weight +
                                      weight * (kt * fresnel.tolerance + 4 * kU * reflect_weight);
                const ExpectedRay reflected = expected_reflection(shaded.point, offset);
                trace(reflected, key_of(reflected, shaded.point.position), media, left - 1,
                      weight * reflect_weight, error);
            }
            const WideVec refract_weight = kt * (1 - fresnel.value);
            if (through.answer == RefractionAnswer::direction && refract_weight != WideVec(0)) {
                const WideVec error = weight_error * refract_weight +
                                      weight * (kt * fresnel.tolerance + 4 * kU * refract_weight);
                trace(through.ray, key_of(through.ray, shaded.point.position), beyond, left - 1,
                      weight * refract_weight, error);
            }
        };
    const ExpectedRay eye_ray{DoubleDoubleVec3(eye.origin),
                              DoubleDouble(),
                              DoubleDoubleVec3(eye.direction),
                              DoubleDouble(),
                              eye.t_min,
                              eye.t_max,
                              std::nullopt};
    trace(eye_ray, eye, inside, bounces, WideVec(1), WideVec(0));
    e.colour_tolerance += Wide(4 * (traced + 4)) * kU * terms;
    return e;
}

}  // namespace raystep
