#include "base/scene/sample_pattern.h"

namespace raystep {

std::string_view sample_pattern_name(SamplePattern pattern) {
    switch (pattern) {
        case SamplePattern::jittered:
            return "jittered";
        case SamplePattern::regular:
            return "regular";
        case SamplePattern::random:
            return "random";
    }
    return "unknown";
}

std::optional<SamplePattern> parse_sample_pattern(std::string_view name) {
    for (const SamplePattern pattern :
         {SamplePattern::jittered, SamplePattern::regular, SamplePattern::random}) {
        if (name == sample_pattern_name(pattern)) return pattern;
    }
    return std::nullopt;
}

}  // namespace raystep
