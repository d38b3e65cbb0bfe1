#include "base/scene/scene_parser.h"

#include <array>

#include "base/errors/input_error.h"
#include "base/scene/sample_pattern.h"
#include "base/scene/text_fields.h"

namespace raystep::scene_parsing {

// Sampling (stage 8). Jittered and regular patterns and stratified light samples need n x n
// samples; the commands may come in any order, so check_sample_grids checks at the end.

int SceneParser::sample_count(std::string_view what) const {
    const long n = count(1, what);
    if (n < 1) fail(std::string(what) + " must be at least 1");
    if (n > kMaxSamples) {
        fail(std::string(what) + " " + std::to_string(n) + " is above the limit of " +
             std::to_string(kMaxSamples) +
             ": at one ray each, a 640 x 480 render of more would not finish in a day");
    }
    return static_cast<int>(n);
}

void SceneParser::spp() {
    once();
    scene_.samples_per_pixel = sample_count("the sample count");
}

void SceneParser::pixelsampling() {
    once();
    constexpr std::array<SamplePattern, 3> patterns = {
        SamplePattern::jittered, SamplePattern::regular, SamplePattern::random};
    scene_.pixel_sampling = patterns[keyword(1, "jittered|regular|random")];
}

void SceneParser::lightsamples() {
    once();
    scene_.light_samples = sample_count("the sample count");
}

void SceneParser::lightstratify() {
    once();
    scene_.light_stratify = keyword(1, "on|off") == 0;
}

void SceneParser::seed() {
    once();
    scene_.seed = parse_unsigned64(fields_[1], {name_, line_}, "the seed");
}

// A non-square spp under the default pattern falls back to random sampling with a note,
// because the CSE168 course, whose scenes must load as written, allows any spp; once a file
// asks for jittered or regular sampling by name, it is an error.
void SceneParser::check_sample_grids() {
    const int spp = scene_.samples_per_pixel;
    if (!fills_square_grid(spp) && scene_.pixel_sampling != SamplePattern::random) {
        const std::uint32_t pattern_line = line_of("pixelsampling");
        if (pattern_line != 0) {
            throw InputError(
                name_, static_cast<int>(line_of("spp")),
                "spp " + std::to_string(spp) + " is not a square, and 'pixelsampling " +
                    std::string(sample_pattern_name(scene_.pixel_sampling)) + "' on line " +
                    std::to_string(pattern_line) +
                    " places n x n samples; give a square (4, 9, 16, ...) or 'pixelsampling "
                    "random'");
        }
        scene_.pixel_sampling = SamplePattern::random;
        scene_.notes.push_back(
            {line_of("spp"), "spp",
             "spp " + std::to_string(spp) +
                 " is not a square, so the samples are spread at random over each pixel "
                 "rather than jittered in n x n strata; give a square for jittered sampling, "
                 "or 'pixelsampling random' to choose random sampling"});
    }
    if (scene_.light_stratify && !fills_square_grid(scene_.light_samples)) {
        throw InputError(name_, static_cast<int>(line_of("lightsamples")),
                         "lightsamples " + std::to_string(scene_.light_samples) +
                             " is not a square, and 'lightstratify on' on line " +
                             std::to_string(line_of("lightstratify")) +
                             " places n x n samples on each light; give a square (4, 9, "
                             "16, ...) or 'lightstratify off'");
    }
}

}  // namespace raystep::scene_parsing
