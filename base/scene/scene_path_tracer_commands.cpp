#include "base/scene/scene_parser.h"

namespace raystep::scene_parsing {

// The CSE168 path tracer's settings. `integrator pathtracer` renders by stage 10's path
// (docs/stage10.md), which reads all of them; under the other integrators they change nothing
// and are noted. `integrator` also sets the dialect (SceneDialect), which scene_loader.cpp reads
// from the whole file before this runs.

namespace {

const char* const kDialect =
    "read in the CSE168 dialect: no ambient unless written, specular as a glossy lobe with no "
    "mirror ray, quad lights drawn, maxverts a declaration, maxdepth -1 for no limit "
    "(docs/scene-format.md, \"Dialects\")";

}  // namespace

void SceneParser::integrator() {
    once();
    scene_.integrator =
        static_cast<Integrator>(keyword(1, "raytracer|direct|analyticdirect|pathtracer"));
    switch (scene_.integrator) {
        case Integrator::direct:
            note("'integrator direct': " + std::string(kDialect));
            break;
        case Integrator::analyticdirect:
            note("'integrator analyticdirect': " + std::string(kDialect) +
                 "; each quad light is integrated exactly over its area, with no shadows and no "
                 "specular, as the course's integrator does");
            break;
        case Integrator::pathtracer:
            note("'integrator pathtracer': " + std::string(kDialect) +
                 "; path-traced by stage 10 (docs/stage10.md), its lights only the quad lights");
            break;
        case Integrator::raytracer:
            break;
    }
}

bool SceneParser::path_traced() const {
    return scene_.integrator == Integrator::pathtracer;
}

void SceneParser::nexteventestimation() {
    once();
    const NextEvent choices[] = {NextEvent::on, NextEvent::off, NextEvent::mis};
    scene_.next_event = choices[keyword(1, "on|off|mis")];
    if (!path_traced()) note("'nexteventestimation' has no effect outside 'integrator pathtracer'");
}

void SceneParser::russianroulette() {
    once();
    scene_.russian_roulette = keyword(1, "on|off") == 0;
    if (!path_traced()) note("'russianroulette' has no effect outside 'integrator pathtracer'");
}

void SceneParser::importancesampling() {
    once();
    scene_.importance_sampling =
        static_cast<DirectionSampling>(keyword(1, "hemisphere|cosine|brdf"));
    if (!path_traced()) note("'importancesampling' has no effect outside 'integrator pathtracer'");
}

void SceneParser::brdf() {
    material_.brdf = static_cast<BrdfModel>(keyword(1, "phong|ggx"));
    material_id_ = kUnregistered;
    if (!cse168()) {
        note(
            "'brdf' has no effect in the CSE167 dialect: every surface has the local model of "
            "docs/stage6.md");
    } else if (material_.brdf == BrdfModel::ggx && !path_traced()) {
        note(
            "'brdf ggx': the direct integrators shade by the course's Phong lobe, so these "
            "surfaces take it; 'integrator pathtracer' shades them by GGX");
    }
}

void SceneParser::roughness() {
    const double alpha = number(1, "the roughness");
    if (!(alpha >= 0.0)) fail("roughness " + std::string(fields_[1]) + " must not be negative");
    material_.roughness = alpha;
    material_id_ = kUnregistered;
    if (!path_traced()) note("'roughness' has no effect outside 'integrator pathtracer'");
}

void SceneParser::gamma() {
    once();
    const double g = number(1, "gamma");
    if (!(g > 0.0)) fail("gamma " + std::string(fields_[1]) + " must be positive");
    note("'gamma' has no effect: raystep writes colours as it computes them");
}

}  // namespace raystep::scene_parsing
