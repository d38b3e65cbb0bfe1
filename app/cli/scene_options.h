#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "base/scene/scene.h"

namespace raystep {

// The options of `render` and `trace` that change a scene's settings for one run, so that a scene
// can be tried another way without editing it: the eye, where secondary rays start, and how
// pixels are sampled. An option not given leaves the scene's own setting.

/// `--lookfrom X Y Z`: the scene's eye moved there, the rest of its camera kept (what it looks at,
/// the up hint, the field of view). The grader renders each scene from an eye of its own
/// (docs/student-README.md, "Grade your work before you hand it in"), and this renders or traces
/// the same view here.
void add_eye_option(CLI::App& command, std::vector<double>& lookfrom);

/// The scene with the eye the command line gives, if any. Throws std::invalid_argument when the
/// eye is the scene's look-at point, from which the camera looks nowhere.
void apply_eye(const std::vector<double>& lookfrom, Scene& scene);

/// `--ray-offset RULE [--epsilon E]`: overrides the scene's `rayoffset` (docs/stage6.md).
struct RayOffsetArguments {
    std::string rule;  ///< empty: the scene's own
    double epsilon = 0.0;

    /// The options as given, for a second raystep that must do the same (trace --compare).
    std::string command_line() const;
};

/// The options on a command; parsing fails (a command-line error) when the epsilon is missing for
/// along-ray or along-normal, or given to error-bound or without a rule.
void add_ray_offset_options(CLI::App& command, RayOffsetArguments& arguments);

/// The scene with the rule the command line gives, if any.
void apply_ray_offset(const RayOffsetArguments& arguments, Scene& scene);

/// `--spp N`, `--pixel-sampling jittered|regular|random` and `--seed S`: a scene's stage-8
/// settings (`spp`, `pixelsampling`, `seed`), to try a scene at another sample count.
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
