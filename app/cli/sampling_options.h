#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "base/scene/scene.h"

namespace raystep {

/// `--spp N`, `--pixel-sampling jittered|regular|random` and `--seed S`: a scene's stage-8
/// settings (`spp`, `pixelsampling`, `seed`) overridden from the command line, to try a scene at
/// another sample count without editing it. Unset, the scene's own hold.
struct SamplingArguments {
    int samples_per_pixel = 0;  ///< 0: the scene's
    std::string pixel_sampling;
    std::optional<std::uint64_t> seed;
};

/// Adds the three options to a command.
void add_sampling_options(CLI::App& command, SamplingArguments& arguments);

/// The scene with the options that were given in place of its settings. Throws
/// std::invalid_argument when the sample count that results does not fit the pattern: jittered
/// and regular need a square count (n x n strata).
void apply_sampling(const SamplingArguments& arguments, Scene& scene);

}  // namespace raystep
