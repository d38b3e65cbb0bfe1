#pragma once

#include <map>
#include <string>
#include <vector>

#include "base/scene/scene.h"

namespace raystep {

// The controls of `raystep view`: what a lecturer turns while the class watches, each a setting
// of the scene file that the page overrides for the next render without editing the file. They
// are the parameters of the lecture demos: the shadow-ray offset of shadow-acne, the samples of
// aliasing and soft-shadows, the index of refraction.

/// One control as the page draws it.
struct SceneControl {
    std::string name;   ///< the query parameter: "epsilon"
    std::string label;  ///< what the page writes beside it
    std::string kind;   ///< "choice" (of `choices`) or "number"
    std::vector<std::string> choices;
    std::string scene_value;  ///< the scene's own setting, as the control shows it
};

/// The controls that apply to `scene`: the ray offset where a light casts shadows; samples per
/// pixel, their pattern and the seed; light samples where there is a quad light; the index of
/// refraction where a material transmits.
std::vector<SceneControl> scene_controls(const Scene& scene);

/// The scene with the controls' values in place of its own settings. An empty value keeps the
/// scene's. Throws std::invalid_argument naming the control for a value that is not one it takes
/// (a rule by another name, a non-square count for a stratified pattern, a negative index).
void apply_scene_controls(const std::map<std::string, std::string>& values, Scene& scene);

/// True when a value differs from the scene's own, so that the reference trace, recorded with the
/// scene's settings, no longer describes the render.
bool controls_change_scene(const std::map<std::string, std::string>& values, const Scene& scene);

}  // namespace raystep
