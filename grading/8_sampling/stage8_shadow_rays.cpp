#include "grading/8_sampling/stage8_shadow_rays.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "app/grade/value_text.h"
#include "grader/oracle/wide_vec.h"
#include "grading/8_sampling/sampling_oracle.h"

namespace raystep::grade {

namespace {

// A unit direction in double is within a few ulps of length 1; 1e-9 accepts any way of
// computing it and refuses a direction left unnormalized.
constexpr Wide kUnitSlack = 1e-9L;
// A light sample u recovered from where a ray meets the light is within rounding (1e-15 of the
// light's size) of the u that made it; 1e-9 of the light accepts that and nothing off it.
constexpr Wide kOnLightSlack = 1e-9L;
// Where a blocker's answer is decided within rounding: t within 1e-12 of its size of an end of
// the ray's range, or the crossing within 1e-12 of the parallelogram's edge. The probe decides
// in double, the grader in long double; here either answer is right.
constexpr Wide kBlockerBand = 1e-12L;
// The sum of n blinn_phong terms in double rounds by a few ulps of each (the highlight's power
// by its exponent's), far below 1e-9 of their sum.
constexpr Wide kColourSlack = 1e-9L;

enum class Blocked { no, yes, either };

// Whether `ray` crosses `p` within its t range, in long double; `either` within rounding of an
// edge of the decision.
Blocked crosses(const Parallelogram& p, const Ray& ray) {
    const WideVec origin = widen(ray.origin);
    const WideVec direction = widen(ray.direction);
    const WideVec corner = widen(p.corner);
    const WideVec e1 = widen(p.edge1);
    const WideVec e2 = widen(p.edge2);
    const WideVec normal = glm::cross(e1, e2);
    const Wide facing = glm::dot(direction, normal);
    if (facing == 0) return Blocked::no;
    const Wide t = glm::dot(corner - origin, normal) / facing;
    const Wide t_band = kBlockerBand * (1 + std::abs(t) + glm::length(corner - origin));
    const Wide t_min = ray.t_min;
    const Wide t_max = ray.t_max;
    if (t < t_min - t_band || t > t_max + t_band) return Blocked::no;
    // The crossing's coordinates along the two edges, by the dual basis of (e1, e2).
    const WideVec q = origin + t * direction - corner;
    const Wide g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
    const Wide det = g11 * g22 - g12 * g12;
    const Wide s = (glm::dot(q, e1) * g22 - glm::dot(q, e2) * g12) / det;
    const Wide r = (glm::dot(q, e2) * g11 - glm::dot(q, e1) * g12) / det;
    if (s < -kBlockerBand || s > 1 + kBlockerBand || r < -kBlockerBand || r > 1 + kBlockerBand) {
        return Blocked::no;
    }
    const bool inside = t >= t_min + t_band && t <= t_max - t_band && s >= kBlockerBand &&
                        s <= 1 - kBlockerBand && r >= kBlockerBand && r <= 1 - kBlockerBand;
    return inside ? Blocked::yes : Blocked::either;
}

Blocked blocked_by(const std::vector<Parallelogram>& blockers, const Ray& ray) {
    Blocked result = Blocked::no;
    for (const Parallelogram& p : blockers) {
        const Blocked b = crosses(p, ray);
        if (b == Blocked::yes) return Blocked::yes;
        if (b == Blocked::either) result = Blocked::either;
    }
    return result;
}

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// How far from the point a right shadow ray may start: the offset rule's epsilon, or for the
// error bound the point's rounding error along the normal and an ulp of each coordinate more.
Wide offset_reach(const QuadLightCall& call) {
    const WideVec position = widen(call.point.position);
    const Wide scale =
        1 + std::max({std::abs(position.x), std::abs(position.y), std::abs(position.z)});
    const Wide error = glm::length(widen(call.point.error));
    const Wide epsilon = call.offset.rule == OffsetRule::error_bound ? 0 : call.offset.epsilon;
    return (epsilon + 2 * error) * (1 + kUnitSlack) + 4 * kWideUnitRoundoff * scale;
}

// Where the line from the point along `direction` meets the light's plane: the light sample u,
// along the light's edges, that a ray in that direction was traced to, and its distance.
struct LightCrossing {
    Vec2 u;
    Wide distance = 0;
};

std::optional<LightCrossing> light_crossing(const QuadLightCall& call, const WideVec& direction) {
    const WideVec corner = widen(call.light.corner);
    const WideVec e1 = widen(call.light.edge1);
    const WideVec e2 = widen(call.light.edge2);
    const WideVec normal = glm::cross(e1, e2);
    const WideVec point = widen(call.point.position);
    const Wide facing = glm::dot(direction, normal);
    if (facing == 0) return std::nullopt;
    const Wide distance = glm::dot(corner - point, normal) / facing;
    if (!(distance > 0)) return std::nullopt;
    const WideVec q = point + distance * direction - corner;
    const Wide g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
    const Wide det = g11 * g22 - g12 * g12;
    return LightCrossing{
        {static_cast<double>((glm::dot(q, e1) * g22 - glm::dot(q, e2) * g12) / det),
         static_cast<double>((glm::dot(q, e2) * g11 - glm::dot(q, e1) * g12) / det)},
        distance};
}

// Why `traced` is not a shadow ray of `call` to the sample `u` it points at; empty when it is.
std::string shadow_ray_problem(const QuadLightCall& call, const TracedShadowRay& traced, Vec2& u) {
    const Ray& ray = traced.ray;
    const std::string which = "the shadow ray " + ray_text(ray);
    if (!finite(ray.origin) || !finite(ray.direction) || std::isnan(ray.t_min) ||
        std::isnan(ray.t_max)) {
        return which + " is not finite";
    }
    const WideVec direction = widen(ray.direction);
    if (!(std::abs(glm::length(direction) - 1) <= kUnitSlack)) return which + " is not unit";
    const Wide reach = offset_reach(call);
    if (!(glm::length(widen(ray.origin) - widen(call.point.position)) <= reach)) {
        return which + " starts more than " + full_text(static_cast<double>(reach)) +
               " from the point " + full_text(call.point.position);
    }
    const std::optional<LightCrossing> crossing = light_crossing(call, direction);
    if (!crossing) return which + " points away from the light's plane";
    u = crossing->u;
    if (!(u.x >= -kOnLightSlack && u.x <= 1 + kOnLightSlack && u.y >= -kOnLightSlack &&
          u.y <= 1 + kOnLightSlack)) {
        return which + " points past the light, at u = (" + full_text(u.x) + ", " + full_text(u.y) +
               ")";
    }
    if (!(ray.t_min >= 0 && ray.t_min < ray.t_max)) return which + " has an empty t range";
    // A right ray ends at its sample: its distance from the point, give or take the offset.
    if (!(ray.t_max <= crossing->distance * (1 + kUnitSlack) + reach)) {
        return which + " goes on past its light sample at distance " +
               full_text(static_cast<double>(crossing->distance));
    }
    return "";
}

}  // namespace

ShadowRayReading read_shadow_rays(const QuadLightCall& call,
                                  const std::vector<TracedShadowRay>& rays) {
    ShadowRayReading reading;
    WideVec sum(0);
    WideVec magnitude(0);
    for (const TracedShadowRay& traced : rays) {
        Vec2 u;
        const std::string problem = shadow_ray_problem(call, traced, u);
        if (!problem.empty()) {
            reading.problem = problem;
            return reading;
        }
        reading.samples.push_back(u);
        // Behind the surface: N . L <= 0 with the shading normal, as blinn_phong has it
        if (!(glm::dot(widen(traced.ray.direction), widen(call.point.shading_normal)) > 0)) {
            ++reading.behind;
        }
        // The blocker's answer, against the grader's own test
        const Blocked blocked = blocked_by(call.blockers, traced.ray);
        if (blocked != Blocked::either && (blocked == Blocked::yes) != traced.blocked) {
            reading.problem = "the blocker's answer for the shadow ray " + ray_text(traced.ray) +
                              " was " + (traced.blocked ? "blocked" : "not blocked") +
                              ", which it is not";
            return reading;
        }
        if (traced.blocked) continue;
        const WideVec term = widen(quad_light_term(call.material, call.point, call.light, u)) /
                             Wide(call.sample_count);
        sum += term;
        magnitude += glm::abs(term);
    }
    reading.colour = narrow(sum);
    reading.tolerance = narrow(kColourSlack * magnitude) + Color(1e-300);
    return reading;
}

std::string colour_problem(const Color& colour, const Color& expected, const Color& tolerance) {
    for (int c = 0; c < 3; ++c) {
        if (!(std::abs(colour[c] - expected[c]) <= tolerance[c])) {
            return "the colour " + full_text(colour) + ", where the shadow rays traced make " +
                   full_text(expected);
        }
    }
    return "";
}

}  // namespace raystep::grade
