#include "base/scene/scene_parser.h"

namespace raystep::scene_parsing {

// The CSE168 path tracer's settings. raystep renders direct light (and stage 9's refraction), no
// indirect light: each of these is read and checked so that the course's scenes load, and noted
// where it changes nothing or renders otherwise than in the course. `integrator` also sets the
// dialect (SceneDialect), which scene_loader.cpp reads from the whole file before this runs.

void SceneParser::integrator() {
    once();
    const std::string dialect =
        "read in the CSE168 dialect: no ambient unless written, specular as a glossy lobe with "
        "no mirror ray, quad lights drawn, maxverts a declaration, maxdepth -1 for no limit "
        "(docs/scene-format.md, \"Dialects\")";
    scene_.integrator =
        static_cast<Integrator>(keyword(1, "raytracer|direct|analyticdirect|pathtracer"));
    switch (scene_.integrator) {
        case Integrator::direct:
            note("'integrator direct': " + dialect);
            break;
        case Integrator::analyticdirect:
            note("'integrator analyticdirect': " + dialect +
                 "; each quad light is integrated exactly over its area, with no shadows and no "
                 "specular, as the course's integrator does");
            break;
        case Integrator::pathtracer:
            note("'integrator pathtracer': " + dialect +
                 "; raystep renders direct light only, no indirect light, so the image is darker "
                 "than a path tracer's");
            break;
        case Integrator::raytracer:
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
        "random");
}

void SceneParser::importancesampling() {
    once();
    keyword(1, "hemisphere|cosine|brdf");
    note(
        "'importancesampling' has no effect: raystep samples the lights, never directions "
        "from a surface");
}

void SceneParser::brdf() {
    const bool phong = keyword(1, "phong|ggx") == 0;
    if (!cse168()) {
        note(
            "'brdf' has no effect in the CSE167 dialect: every surface has the local model of "
            "docs/stage6.md");
    } else if (!phong) {
        note(
            "'brdf ggx': raystep has no GGX lobe, so these surfaces take the course's Phong "
            "lobe");
    }
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
