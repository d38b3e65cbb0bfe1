#include "app/view/scene_controls.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "base/scene/ray_offset.h"
#include "base/scene/sample_pattern.h"
#include "base/scene/scene_features.h"

namespace raystep {

namespace {

const std::string* value_of(const std::map<std::string, std::string>& values,
                            const std::string& name) {
    const auto found = values.find(name);
    return found == values.end() || found->second.empty() ? nullptr : &found->second;
}

// strtod, not stod: stod refuses a number below the smallest normal double (1e-320) as out of
// range, where strtod gives the subnormal it is.
double number_of(const std::string& name, const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || std::isnan(value)) {
        throw std::invalid_argument("control " + name + ": '" + text + "' is not a number");
    }
    if (!std::isfinite(value)) {
        throw std::invalid_argument("control " + name + ": '" + text +
                                    "' is beyond the largest double");
    }
    return value;
}

int count_of(const std::string& name, const std::string& text, int largest) {
    const double value = number_of(name, text);
    if (value < 1 || value > largest || value != std::floor(value)) {
        throw std::invalid_argument("control " + name + ": '" + text +
                                    "' is not a whole number from 1 to " + std::to_string(largest));
    }
    return static_cast<int>(value);
}

std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

bool transmits(const Material& material) {
    return material.transmission != Color(0.0);
}

}  // namespace

std::vector<SceneControl> scene_controls(const Scene& scene) {
    std::vector<SceneControl> controls;
    const SceneFeatures features = scene_features(scene);
    if (features.uses_lights()) {
        controls.push_back({"offset",
                            "shadow-ray offset",
                            "choice",
                            {"error-bound", "along-ray", "along-normal"},
                            std::string(offset_rule_name(scene.ray_offset.rule))});
        controls.push_back({"epsilon",
                            "epsilon (along-ray, along-normal)",
                            "number",
                            {},
                            number_text(scene.ray_offset.epsilon)});
    }
    if (features.uses_sampling()) {
        controls.push_back(
            {"spp", "samples per pixel", "number", {}, std::to_string(scene.samples_per_pixel)});
        controls.push_back({"pixelsampling",
                            "pixel sampling",
                            "choice",
                            {"jittered", "regular", "random"},
                            std::string(sample_pattern_name(scene.pixel_sampling))});
        controls.push_back({"seed", "seed", "number", {}, std::to_string(scene.seed)});
    }
    if (features.quad_lights > 0) {
        controls.push_back({"lightsamples",
                            "light samples per quad light",
                            "number",
                            {},
                            std::to_string(scene.light_samples)});
        controls.push_back({"lightstratify",
                            "stratified light samples",
                            "choice",
                            {"on", "off"},
                            scene.light_stratify ? "on" : "off"});
    }
    if (features.uses_refraction()) {
        for (const Material& material : scene.materials) {
            if (transmits(material)) {
                controls.push_back({"ior",
                                    "index of refraction of every glass",
                                    "number",
                                    {},
                                    number_text(material.index)});
                break;
            }
        }
    }
    return controls;
}

void apply_scene_controls(const std::map<std::string, std::string>& values, Scene& scene) {
    if (const std::string* rule = value_of(values, "offset")) {
        const auto parsed = parse_offset_rule(*rule);
        if (!parsed) {
            throw std::invalid_argument("control offset: '" + *rule +
                                        "' is none of error-bound, along-ray, along-normal");
        }
        scene.ray_offset.rule = *parsed;
        scene.ray_offset.epsilon = 0.0;
        if (uses_epsilon(*parsed)) {
            const std::string* epsilon = value_of(values, "epsilon");
            if (!epsilon) {
                throw std::invalid_argument("control offset: " + *rule +
                                            " needs epsilon, the offset distance");
            }
            // Zero is taken, unlike in a scene file: it is the lecture's first case (shadow-acne's
            // "epsilon = 0" panel), the shadow ray started on the surface it leaves.
            scene.ray_offset.epsilon = number_of("epsilon", *epsilon);
            if (!(scene.ray_offset.epsilon >= 0.0)) {
                throw std::invalid_argument("control epsilon: the offset distance must be >= 0");
            }
        }
    }
    if (const std::string* spp = value_of(values, "spp"))
        scene.samples_per_pixel = count_of("spp", *spp, kMaxSamples);
    if (const std::string* pattern = value_of(values, "pixelsampling")) {
        const auto parsed = parse_sample_pattern(*pattern);
        if (!parsed) {
            throw std::invalid_argument("control pixelsampling: '" + *pattern +
                                        "' is none of jittered, regular, random");
        }
        scene.pixel_sampling = *parsed;
    }
    if (scene.pixel_sampling != SamplePattern::random &&
        !fills_square_grid(scene.samples_per_pixel)) {
        throw std::invalid_argument("control spp: " + std::to_string(scene.samples_per_pixel) +
                                    " samples cannot be placed " +
                                    std::string(sample_pattern_name(scene.pixel_sampling)) +
                                    ": it needs n x n strata (4, 9, 16, ...); or choose random");
    }
    if (const std::string* seed = value_of(values, "seed")) {
        const double value = number_of("seed", *seed);
        if (value < 0 || value > 9007199254740992.0 || value != std::floor(value)) {
            throw std::invalid_argument("control seed: '" + *seed +
                                        "' is not a whole number from 0 to 2^53");
        }
        scene.seed = static_cast<std::uint64_t>(value);
    }
    if (const std::string* samples = value_of(values, "lightsamples"))
        scene.light_samples = count_of("lightsamples", *samples, kMaxSamples);
    if (const std::string* stratify = value_of(values, "lightstratify")) {
        if (*stratify != "on" && *stratify != "off") {
            throw std::invalid_argument("control lightstratify: '" + *stratify +
                                        "' is neither on nor off");
        }
        scene.light_stratify = *stratify == "on";
    }
    if (scene.light_stratify && !fills_square_grid(scene.light_samples)) {
        throw std::invalid_argument(
            "control lightsamples: stratified light samples need n x n "
            "strata (4, 9, 16, ...), not " +
            std::to_string(scene.light_samples));
    }
    if (const std::string* ior = value_of(values, "ior")) {
        const double index = number_of("ior", *ior);
        if (!(index > 0.0)) throw std::invalid_argument("control ior: the index must be > 0");
        for (Material& material : scene.materials) {
            if (transmits(material)) material.index = index;
        }
    }
}

bool controls_change_scene(const std::map<std::string, std::string>& values, const Scene& scene) {
    Scene changed = scene;
    apply_scene_controls(values, changed);
    bool same_index = true;
    for (std::size_t k = 0; k < scene.materials.size(); ++k)
        same_index = same_index && scene.materials[k] == changed.materials[k];
    return !(changed.ray_offset == scene.ray_offset &&
             changed.samples_per_pixel == scene.samples_per_pixel &&
             changed.pixel_sampling == scene.pixel_sampling && changed.seed == scene.seed &&
             changed.light_samples == scene.light_samples &&
             changed.light_stratify == scene.light_stratify && same_index);
}

}  // namespace raystep
