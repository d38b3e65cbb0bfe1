#include "base/scene/sample_pattern.h"

#include <cmath>

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

bool fills_square_grid(int count) {
    if (count < 1) return false;
    // The square root of an int is within half of its rounding: exact for every count a scene
    // can hold (far below 2^52).
    const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(count))));
    return side * side == count;
}

}  // namespace raystep
