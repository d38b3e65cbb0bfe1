#include "base/scene/ray_offset.h"

namespace raystep {

std::string_view offset_rule_name(OffsetRule rule) {
    switch (rule) {
        case OffsetRule::along_ray:
            return "along-ray";
        case OffsetRule::along_normal:
            return "along-normal";
        case OffsetRule::error_bound:
            return "error-bound";
    }
    return "unknown";
}

std::optional<OffsetRule> parse_offset_rule(std::string_view name) {
    for (const OffsetRule rule :
         {OffsetRule::along_ray, OffsetRule::along_normal, OffsetRule::error_bound}) {
        if (name == offset_rule_name(rule)) return rule;
    }
    return std::nullopt;
}

bool uses_epsilon(OffsetRule rule) {
    return rule != OffsetRule::error_bound;
}

}  // namespace raystep
