#pragma once

#include <optional>
#include <string_view>

namespace raystep {

/// How the samples of a pixel are placed (`pixelsampling`, `raystep render --pixel-sampling`).
enum class SamplePattern {
    jittered,  ///< one random point in each of n x n strata (spp = n^2)
    regular,   ///< the centres of the n x n strata: supersampling, no noise, still aliased
    random,    ///< spp points uniform over the pixel
};

/// "jittered", "regular", "random": the pattern's name in scenes, on the command line and in the
/// probe's calls.
std::string_view sample_pattern_name(SamplePattern pattern);

/// The pattern with this name; nullopt when none has it.
std::optional<SamplePattern> parse_sample_pattern(std::string_view name);

/// Whether `count` samples fill an n x n grid of strata (n at least 1), as jittered and regular
/// place them.
bool fills_square_grid(int count);

}  // namespace raystep
