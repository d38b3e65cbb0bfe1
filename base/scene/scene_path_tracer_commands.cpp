#include "base/scene/scene_parser.h"

namespace raystep::scene_parsing {

// The CSE168 path tracer's settings. raystep renders direct light and mirrors (and stage 9's
// refraction), no indirect light: each of these is read and checked so that the course's
// scenes load, and noted where it changes nothing or renders otherwise than in the course.

void SceneParser::integrator() {
    once();
    switch (keyword(1, "raytracer|direct|analyticdirect|pathtracer")) {
        case 2:
            note(
                "'integrator analyticdirect': raystep samples each quad light "
                "('lightsamples') rather than integrating it exactly, so soft shadows are "
                "noisy where the course's are not");
            break;
        case 3:
            note(
                "'integrator pathtracer': raystep renders direct light and mirror "
                "reflection only, no indirect light, so the image is darker than a path "
                "tracer's");
            break;
        default:
            break;
    }
}

void SceneParser::nexteventestimation() {
    once();
    keyword(1, "on|off|mis");
    note(
        "'nexteventestimation' has no effect: raystep traces no indirect paths and always "
        "samples the lights");
}

void SceneParser::russianroulette() {
    once();
    keyword(1, "on|off");
    note(
        "'russianroulette' has no effect: raystep traces no indirect paths to end at "
        "random; maxdepth bounds its mirror bounces");
}

void SceneParser::importancesampling() {
    once();
    keyword(1, "hemisphere|cosine|brdf");
    note(
        "'importancesampling' has no effect: raystep samples the lights, never directions "
        "from a surface");
}

void SceneParser::brdf() {
    keyword(1, "phong|ggx");
    note(
        "'brdf' has no effect: raystep shades every surface with the CSE167 local model "
        "(docs/stage6.md)");
}

void SceneParser::roughness() {
    const double alpha = number(1, "the roughness");
    if (!(alpha >= 0.0)) fail("roughness " + std::string(fields_[1]) + " must not be negative");
    note("'roughness' has no effect: raystep has no GGX surfaces");
}

void SceneParser::gamma() {
    once();
    const double g = number(1, "gamma");
    if (!(g > 0.0)) fail("gamma " + std::string(fields_[1]) + " must be positive");
    note("'gamma' has no effect: raystep writes colours as it computes them");
}

}  // namespace raystep::scene_parsing
