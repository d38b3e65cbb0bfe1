#include "app/cli/sampling_options.h"

#include <stdexcept>

#include "base/scene/sample_pattern.h"

namespace raystep {

namespace {

// The loader's ceiling on `spp` (docs/scene-format.md), so that the option cannot ask for more
// than a scene may.
constexpr int kMostSamplesPerPixel = 1 << 16;

}  // namespace

void add_sampling_options(CLI::App& command, SamplingArguments& arguments) {
    command
        .add_option("--spp", arguments.samples_per_pixel,
                    "Samples per pixel, in place of the scene's spp (a square for jittered and "
                    "regular sampling)")
        ->check(CLI::Range(1, kMostSamplesPerPixel));
    command
        .add_option("--pixel-sampling", arguments.pixel_sampling,
                    "Where a pixel's samples go, in place of the scene's pixelsampling")
        ->check(CLI::IsMember({"jittered", "regular", "random"}));
    // CLI11 reads "-1" into an unsigned 64-bit number as 2^64 - 1, as strtoull does; the scene's
    // `seed` refuses it, and so does the option.
    command
        .add_option("--seed", arguments.seed,
                    "The random seed, in place of the scene's seed: another seed, other noise")
        ->check(
            [](const std::string& text) {
                return text.find('-') == std::string::npos
                           ? std::string()
                           : std::string("the seed is a whole number from 0 to 2^64 - 1");
            },
            "0 to 2^64 - 1");
}

void apply_sampling(const SamplingArguments& arguments, Scene& scene) {
    if (arguments.samples_per_pixel > 0) scene.samples_per_pixel = arguments.samples_per_pixel;
    if (const auto pattern = parse_sample_pattern(arguments.pixel_sampling)) {
        scene.pixel_sampling = *pattern;
    }
    if (arguments.seed) scene.seed = *arguments.seed;
    if (scene.pixel_sampling != SamplePattern::random &&
        !fills_square_grid(scene.samples_per_pixel)) {
        throw std::invalid_argument(std::to_string(scene.samples_per_pixel) +
                                    " samples per pixel cannot be placed " +
                                    std::string(sample_pattern_name(scene.pixel_sampling)) +
                                    ": it needs n x n strata (4, 9, 16, ...); " +
                                    "use --spp with a square or --pixel-sampling random");
    }
}

}  // namespace raystep
