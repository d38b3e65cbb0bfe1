#pragma once

#include <optional>
#include <string_view>

namespace raystep {

/// Where a ray leaving a surface (a shadow ray, a mirror ray) starts, so that it does not hit
/// that surface again at t ~ 0 (shadow acne) nor start beyond what is really near it (light
/// leaks). Stage 6 implements the rules; docs/stage6.md compares them.
enum class OffsetRule {
    along_ray,     ///< start at the point and count hits only for t > epsilon
    along_normal,  ///< start epsilon along the normal, on the side the ray leaves to
    error_bound,   ///< start just beyond the point's rounding error along the normal: no epsilon
};

/// `rayoffset rule [epsilon]` in a scene, `--ray-offset` on the command line.
struct RayOffset {
    OffsetRule rule = OffsetRule::error_bound;
    double epsilon = 0.0;  ///< > 0 for along_ray and along_normal; unused by error_bound

    bool operator==(const RayOffset& other) const {
        return rule == other.rule && epsilon == other.epsilon;
    }
};

/// "along-ray", "along-normal", "error-bound": the rule's name in scenes and on the command line.
std::string_view offset_rule_name(OffsetRule rule);

/// The rule with this name; nullopt when none has it.
std::optional<OffsetRule> parse_offset_rule(std::string_view name);

/// True when the rule measures in epsilon (and so needs one).
bool uses_epsilon(OffsetRule rule);

}  // namespace raystep
