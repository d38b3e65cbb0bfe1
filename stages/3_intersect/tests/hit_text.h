#pragma once

#include <optional>
#include <string>

#include "base/testing/number_text.h"
#include "stages/3_intersect/intersect.h"

namespace raystep::testing {

/// How the public tests print a ray, every number exact, so that a failing case can be typed in
/// again: "ray: origin (0, 0, 5), direction (0, 0, -1), t in [0, inf]".
inline std::string text(const Ray& ray) {
    return "ray: origin " + exact_text(ray.origin) + ", direction " + exact_text(ray.direction) +
           ", t in [" + exact_text(ray.t_min) + ", " + exact_text(ray.t_max) + "]";
}

/// How they print closest_hit's answer: "a miss", or "triangle 12 at t = 4.25".
inline std::string text(const std::optional<PrimitiveHit>& hit) {
    if (!hit) return "a miss";
    const char* const kinds[] = {"sphere", "triangle", "plane"};
    return kinds[static_cast<int>(hit->kind)] + (" " + std::to_string(hit->index)) +
           " at t = " + exact_text(hit->hit.t);
}

}  // namespace raystep::testing
