#include "app/cli/scene_options.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <stdexcept>
#include <utility>

#include "base/scene/sample_pattern.h"

namespace raystep {

namespace {

// A CLI11 check of an option's number: the whole text a finite number (strtod's syntax) that
// `accept` takes, any finite one where `accept` is empty. Otherwise the option is refused with
// `problem` and the text: "the offset distance must be a number above 0, not '0'". `name` is what
// CLI11's help shows for the value ("EPSILON").
CLI::Validator finite_number_check(std::string name, std::string problem,
                                   std::function<bool(double)> accept = {}) {
    return CLI::Validator(
        [problem = std::move(problem), accept = std::move(accept)](std::string& text) {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (!text.empty() && *end == '\0' && std::isfinite(value) && (!accept || accept(value)))
                return std::string();
            return problem + ", not '" + text + "'";
        },
        std::move(name));
}

// The loader's ceiling on `spp` (docs/scene-format.md), so that the option cannot ask for more
// than a scene may.
constexpr int kMostSamplesPerPixel = 1 << 16;

}  // namespace

void add_eye_option(CLI::App& command, std::vector<double>& lookfrom) {
    command
        .add_option("--lookfrom", lookfrom,
                    "Render from this eye instead of the scene's: three numbers, the rest of the "
                    "camera kept")
        ->expected(3)
        ->check(finite_number_check("X Y Z", "the eye's coordinates are numbers"));
}

void apply_eye(const std::vector<double>& lookfrom, Scene& scene) {
    if (lookfrom.empty()) return;
    const Vec3 eye(lookfrom[0], lookfrom[1], lookfrom[2]);
    if (eye == scene.camera.lookat) {
        throw std::invalid_argument(
            "--lookfrom is the scene's look-at point: from there the camera looks nowhere");
    }
    scene.camera.lookfrom = eye;
}

std::string RayOffsetArguments::command_line() const {
    if (rule.empty()) return "";
    std::string text = " --ray-offset " + rule;
    if (epsilon > 0.0) {
        char number[32];
        std::snprintf(number, sizeof number, "%.17g", epsilon);  // the same double back
        text += std::string(" --epsilon ") + number;
    }
    return text;
}

void add_ray_offset_options(CLI::App& command, RayOffsetArguments& arguments) {
    command
        .add_option("--ray-offset", arguments.rule,
                    "Where shadow and mirror rays start: error-bound (no epsilon), along-ray or "
                    "along-normal (with --epsilon). Default: the scene's rayoffset, else "
                    "error-bound")
        ->check(CLI::IsMember({"along-ray", "along-normal", "error-bound"}));
    command
        .add_option("--epsilon", arguments.epsilon,
                    "The offset distance of along-ray and along-normal")
        ->check(finite_number_check("EPSILON", "the offset distance must be a number above 0",
                                    [](double value) { return value > 0.0; }));
    // The two options make sense only together: checked once both are read, as a command-line
    // error (exit code 2), before any scene is loaded.
    command.parse_complete_callback([&arguments] {
        const bool has_epsilon = arguments.epsilon > 0.0;
        if (arguments.rule.empty()) {
            if (has_epsilon) {
                throw CLI::ValidationError("--epsilon",
                                           "needs --ray-offset along-ray or along-normal");
            }
            return;
        }
        const bool needs_epsilon = uses_epsilon(*parse_offset_rule(arguments.rule));
        if (needs_epsilon && !has_epsilon) {
            throw CLI::ValidationError("--ray-offset",
                                       arguments.rule + " needs --epsilon, the offset distance");
        }
        if (!needs_epsilon && has_epsilon) {
            throw CLI::ValidationError("--ray-offset",
                                       "error-bound takes no --epsilon: it needs no tuning");
        }
    });
}

void apply_ray_offset(const RayOffsetArguments& arguments, Scene& scene) {
    if (arguments.rule.empty()) return;
    scene.ray_offset = {*parse_offset_rule(arguments.rule), arguments.epsilon};
}

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
