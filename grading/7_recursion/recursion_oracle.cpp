#include "grading/7_recursion/recursion_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "base/math/unit_roundoff.h"

namespace raystep {

ExpectedRay expected_leaving_ray(const SurfacePoint& p, const WideVec& d, Wide direction_tolerance,
                                 const RayOffset& offset) {
    const Wide size = std::max({std::abs(Wide(p.position.x)), std::abs(Wide(p.position.y)),
                                std::abs(Wide(p.position.z)), Wide(offset.epsilon)});
    ExpectedRay e{DoubleDoubleVec3(p.position),
                  double_double(4 * kUnitRoundoff * size),
                  double_double(d),
                  double_double(direction_tolerance),
                  offset.epsilon,
                  std::numeric_limits<double>::infinity(),
                  {}};
    switch (offset.rule) {
        case OffsetRule::along_ray:
            break;
        case OffsetRule::along_normal:
            e.origin = double_double(widen(p.position) +
                                     Wide(offset.epsilon) * leaving_normal(p, narrow(d)));
            e.t_min = 0.0;
            break;
        case OffsetRule::error_bound:
            e.region = error_bound_origin(p, narrow(d));
            e.t_min = 0.0;
            break;
    }
    return e;
}

ExpectedRay expected_reflection(const SurfacePoint& p, const RayOffset& offset) {
    const WideVec v = widen(p.to_eye);
    const WideVec n = widen(p.shading_normal);
    const WideVec d = glm::normalize(-v + 2 * glm::dot(v, n) * n);
    return expected_leaving_ray(p, d, 8 * kUnitRoundoff, offset);
}

ExpectedRadiance expected_radiance(const Script& script, const Ray& eye, int bounces,
                                   const RayOffset& offset) {
    ExpectedRadiance e;
    e.rays.push_back({DoubleDoubleVec3(eye.origin), DoubleDouble(), DoubleDoubleVec3(eye.direction),
                      DoubleDouble(), eye.t_min, eye.t_max, std::nullopt});
    WideVec weight(1);
    // Each term is the local colour times a product of reflectances, all non-negative: a few
    // roundings per product and one per sum, relative to the terms' sum.
    WideVec terms(0);
    int depth = 0;
    for (std::size_t i = 0; i < script.size() && script[i]; ++i) {
        const ShadedHit& hit = *script[i];
        e.colour += weight * widen(hit.local);
        terms += weight * glm::abs(widen(hit.local));
        if (bounces - depth <= 0 || hit.reflectance == Color(0.0)) break;
        weight *= widen(hit.reflectance);
        e.rays.push_back(expected_reflection(hit.point, offset));
        ++depth;
    }
    e.colour_tolerance = Wide(4 * (depth + 2) * kUnitRoundoff) * terms;
    return e;
}

}  // namespace raystep
