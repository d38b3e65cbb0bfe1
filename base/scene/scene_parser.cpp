#include "base/scene/scene_parser.h"

#include <algorithm>
#include <cmath>

#include "base/errors/input_error.h"
#include "base/math/to_text.h"
#include "base/scene/text_fields.h"

namespace raystep::scene_parsing {

void SceneParser::parse_line(std::string_view text) {
    ++line_;
    split_fields(text, fields_);
    if (fields_.empty()) return;

    const Command& command = find_command(fields_[0]);
    const std::size_t given = fields_.size() - 1;
    if (given < command.argument_count || given > command.argument_count + command.optional_count) {
        const std::string count =
            command.optional_count == 0
                ? std::to_string(command.argument_count)
                : std::to_string(command.argument_count) + " or " +
                      std::to_string(command.argument_count + command.optional_count);
        fail("'" + std::string(command.name) + "' takes " + count + " argument" +
             (count == "1" ? "" : "s") +
             (command.arguments.empty() ? "" : " (" + std::string(command.arguments) + ")") +
             ", found " + std::to_string(given));
    }
    (this->*command.handle)();
    first_uses_.try_emplace(std::string(command.name), static_cast<std::uint32_t>(line_));
}

Scene SceneParser::finish() {
    if (line_of("camera") == 0) {
        throw InputError(name_, 0, "the scene has no 'camera' command, so nothing can be seen");
    }
    scene_.camera.ortho = ortho_;
    check_sample_grids();
    if (path_traced()) check_path_tracer_scene();
    // analyticdirect integrates each quad light exactly: its samples, wherever they were set,
    // change nothing.
    if (scene_.integrator == Integrator::analyticdirect) {
        for (const std::string command : {"lightsamples", "lightstratify"}) {
            if (const std::uint32_t line = line_of(command)) {
                scene_.notes.push_back({line, command,
                                        "'" + command +
                                            "' has no effect under 'integrator analyticdirect', "
                                            "which integrates each quad light exactly"});
            }
        }
    }
    std::stable_sort(scene_.notes.begin(), scene_.notes.end(),
                     [](const SceneNote& a, const SceneNote& b) { return a.line < b.line; });
    return std::move(scene_);
}

// What the path tracer does not use is noted on its first line (the direct integrators' lights
// and samples, CSE167's mirrors' media); a path that need not end is an error, or, where only a
// material's albedo of 1 keeps it going, noted.
void SceneParser::check_path_tracer_scene() {
    if (scene_.max_depth == kUnboundedDepth && !scene_.russian_roulette) {
        throw InputError(name_, static_cast<int>(line_of("maxdepth")),
                         "maxdepth -1 (no limit) under 'integrator pathtracer' needs "
                         "'russianroulette on': without it a path in a closed room never ends");
    }
    const std::pair<const char*, const char*> unused[] = {
        {"point", "its paths are lit by quad lights and emitting surfaces only"},
        {"directional", "its paths are lit by quad lights and emitting surfaces only"},
        {"spot", "its paths are lit by quad lights and emitting surfaces only"},
        {"background", "a path that leaves the scene sees black, as in the course"},
        {"transmission", "its paths neither refract nor mirror"},
        {"ior", "its paths neither refract nor mirror"},
        {"lightsamples", "next event estimation takes one sample of each light at each hit"},
        {"lightstratify", "next event estimation takes one sample of each light at each hit"},
    };
    for (const auto& [command, why] : unused) {
        if (const auto used = first_uses_.find(command); used != first_uses_.end()) {
            const std::uint32_t line = used->second;
            scene_.notes.push_back({line, command,
                                    "'" + std::string(command) +
                                        "' has no effect under 'integrator pathtracer': " + why});
        }
    }
    if (scene_.max_depth != kUnboundedDepth) return;
    for (const Material& material : scene_.materials) {
        const Color albedo = material.diffuse + material.specular;
        if (std::max({albedo.x, albedo.y, albedo.z}) >= 1.0) {
            scene_.notes.push_back(
                {line_of("maxdepth"), "maxdepth",
                 "a material reflects all the light it gets (Kd + Ks of 1 or more in a channel): "
                 "Russian roulette cannot end its paths, which stop after " +
                     std::to_string(kLongestPath) + " bounces"});
            return;
        }
    }
}

const std::vector<SceneParser::Command>& SceneParser::commands() {
    static const std::vector<Command> table = {
        {"size", "width height", &SceneParser::size},
        {"maxdepth", "depth", &SceneParser::maxdepth},
        {"output", "filename", &SceneParser::output},
        {"camera", "fromx fromy fromz atx aty atz upx upy upz fovy", &SceneParser::camera},
        {"ortho", "left right bottom top", &SceneParser::ortho},
        {"rayoffset", "rule [epsilon]", &SceneParser::rayoffset},
        {"sphere", "x y z radius", &SceneParser::sphere},
        {"plane", "x y z nx ny nz", &SceneParser::plane},
        {"maxverts", "count", &SceneParser::maxverts},
        {"maxvertnorms", "count", &SceneParser::maxvertnorms},
        {"vertex", "x y z", &SceneParser::vertex},
        {"vertexnormal", "x y z nx ny nz", &SceneParser::vertexnormal},
        {"tri", "v0 v1 v2", &SceneParser::tri},
        {"trinormal", "v0 v1 v2", &SceneParser::trinormal},
        {"vertexuv", "x y z u v", &SceneParser::vertexuv},
        {"triuv", "v0 v1 v2", &SceneParser::triuv},
        {"mesh", "file [smooth]", &SceneParser::mesh},
        {"define", "name file [smooth]", &SceneParser::define},
        {"instance", "name", &SceneParser::instance},
        {"translate", "x y z", &SceneParser::translate},
        {"rotate", "axisx axisy axisz degrees", &SceneParser::rotate},
        {"scale", "x y z", &SceneParser::scale},
        {"pushTransform", "", &SceneParser::push_transform},
        {"popTransform", "", &SceneParser::pop_transform},
        {"directional", "x y z r g b", &SceneParser::directional},
        {"point", "x y z r g b", &SceneParser::point},
        {"spot", "x y z dx dy dz cutoff exponent r g b", &SceneParser::spot},
        {"quadLight", "ax ay az abx aby abz acx acy acz r g b", &SceneParser::quad_light},
        {"attenuation", "constant linear quadratic", &SceneParser::attenuation},
        {"background", "r g b", &SceneParser::background},
        {"ambient", "r g b", &SceneParser::ambient},
        {"diffuse", "r g b", &SceneParser::diffuse},
        {"specular", "r g b", &SceneParser::specular},
        {"shininess", "s", &SceneParser::shininess},
        {"emission", "r g b", &SceneParser::emission},
        {"texture", "file|off [repeat|clamp|mirror]", &SceneParser::texture},
        {"normalmap", "file|off [repeat|clamp|mirror]", &SceneParser::normalmap},
        {"bumpmap", "file|off [scale] [repeat|clamp|mirror]", &SceneParser::bumpmap},
        {"transmission", "r g b", &SceneParser::transmission},
        {"ior", "index", &SceneParser::ior},
        {"fresnel", "exact|schlick", &SceneParser::fresnel},
        {"spp", "count", &SceneParser::spp},
        {"pixelsampling", "jittered|regular|random", &SceneParser::pixelsampling},
        {"lightsamples", "count", &SceneParser::lightsamples},
        {"lightstratify", "on|off", &SceneParser::lightstratify},
        {"seed", "number", &SceneParser::seed},
        {"integrator", "raytracer|direct|analyticdirect|pathtracer", &SceneParser::integrator},
        {"nexteventestimation", "on|off|mis", &SceneParser::nexteventestimation},
        {"russianroulette", "on|off", &SceneParser::russianroulette},
        {"importancesampling", "hemisphere|cosine|brdf", &SceneParser::importancesampling},
        {"brdf", "phong|ggx", &SceneParser::brdf},
        {"roughness", "alpha", &SceneParser::roughness},
        {"gamma", "gamma", &SceneParser::gamma},
    };
    return table;
}

const SceneParser::Command& SceneParser::find_command(std::string_view name) const {
    const std::vector<Command>& table = commands();
    const auto found =
        std::find_if(table.begin(), table.end(), [&](const Command& c) { return c.name == name; });
    if (found != table.end()) return *found;

    std::string message = "unknown command " + quoted_field(name);
    // A typo is a few characters off a command; a longer word is not worth measuring.
    if (name.size() <= 20) {
        const auto nearest =
            std::min_element(table.begin(), table.end(), [&](const Command& a, const Command& b) {
                return edit_distance(name, a.name) < edit_distance(name, b.name);
            });
        if (edit_distance(name, nearest->name) <= 2) {
            message += "; did you mean '" + std::string(nearest->name) + "'?";
        }
    }
    fail(message);
}

// Arguments

void SceneParser::fail(const std::string& problem) const {
    throw InputError(name_, line_, problem);
}

double SceneParser::number(std::size_t k, std::string_view what) const {
    const double value = parse_finite_number(fields_[k], {name_, line_}, what);
    if (std::abs(value) > kLargestNumber) {
        fail(std::string(what) + " " + quoted_field(fields_[k]) +
             " is beyond 1e100, the range in which the renderer computes reliably");
    }
    return value;
}

long SceneParser::count(std::size_t k, std::string_view what) const {
    return parse_count(fields_[k], {name_, line_}, what);
}

Vec3 SceneParser::vec3(std::size_t first, std::string_view what) const {
    return {number(first, what), number(first + 1, what), number(first + 2, what)};
}

// A vector used for its direction only.
Vec3 SceneParser::direction(std::size_t first, std::string_view what) const {
    const Vec3 v = vec3(first, "a component of " + std::string(what));
    const double m = largest_magnitude(v);
    if (m == 0.0) fail(std::string(what) + " is zero");
    if (m < kSmallestDirection || m > kLargestDirection) {
        fail(std::string(what) + " " + to_text(v) +
             " is too short or too long to normalize reliably; scale it towards 1");
    }
    return v;
}

Color SceneParser::color(std::size_t first) const {
    const Color c = vec3(first, "a colour component");
    if (c.r < 0 || c.g < 0 || c.b < 0) {
        fail("colour " + to_text(c) + " has a negative component");
    }
    return c;
}

// The value of field k, one of the words of `choices` ("on|off"): its position among them.
std::size_t SceneParser::keyword(std::size_t k, std::string_view choices) const {
    std::vector<std::string_view> words;
    std::size_t start = 0;
    while (start <= choices.size()) {
        const std::size_t bar = std::min(choices.find('|', start), choices.size());
        words.push_back(choices.substr(start, bar - start));
        start = bar + 1;
    }
    const auto found = std::find(words.begin(), words.end(), fields_[k]);
    if (found != words.end()) return static_cast<std::size_t>(found - words.begin());
    std::string listed;
    for (std::size_t w = 0; w < words.size(); ++w) {
        listed += (w == 0 ? "" : w + 1 == words.size() ? " or " : ", ") + std::string(words[w]);
    }
    fail("'" + std::string(fields_[0]) + "' takes " + listed + ", not " + quoted_field(fields_[k]));
}

// A scene-wide setting (`size`, `camera`, `spp`, ...) is given at most once: a second one is
// an error, never a silent override.
void SceneParser::once() {
    const auto [first, inserted] =
        first_lines_.try_emplace(std::string(fields_[0]), static_cast<std::uint32_t>(line_));
    if (!inserted) {
        fail("'" + std::string(fields_[0]) + "' was already given on line " +
             std::to_string(first->second));
    }
}

// The line of a once-only command, 0 when the file has none.
std::uint32_t SceneParser::line_of(const std::string& command) const {
    const auto found = first_lines_.find(command);
    return found == first_lines_.end() ? 0 : found->second;
}

// A note on this line for `scene_.notes`; a command that recurs (`brdf` in every material)
// is noted on its first line only.
void SceneParser::note(const std::string& text) {
    for (const SceneNote& noted : scene_.notes) {
        if (noted.command == fields_[0]) return;
    }
    scene_.notes.push_back({static_cast<std::uint32_t>(line_), std::string(fields_[0]), text});
}

}  // namespace raystep::scene_parsing
