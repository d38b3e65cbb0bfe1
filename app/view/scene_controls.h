#pragma once

#include <map>
#include <string>
#include <vector>

#include "base/scene/scene.h"

namespace raystep {

// The controls of `raystep view`: what a lecturer turns while the class watches, each a setting
// of the scene file that the page overrides for the next render without editing the file. They
// are the parameters of the lecture demos: the shadow-ray offset of shadow-acne, the samples of
// aliasing and soft-shadows, the index of refraction. A scene gets those of the stages it uses
// (its SceneFeatures), so that a stage-2 scene shows no stage-8 sampling.

/// One control as the page draws it.
struct SceneControl {
    std::string name;   ///< the query parameter: "epsilon"
    std::string label;  ///< what the page writes beside it
    std::string kind;   ///< "choice" (of `choices`) or "number"
    std::vector<std::string> choices;
    std::string scene_value;  ///< the scene's own setting, as the control shows it
};

/// The controls of what `scene` uses, by its scene_features: the ray offset where a light casts
/// shadows (stage 6); samples per pixel, their pattern and the seed where it samples (stage 8:
/// more than one sample per pixel, or a quad light); light samples where there is a quad light;
/// the index of refraction where something transmits (stage 9). None for a scene of stages 1 to
/// 5, which has no setting that a control could change.
std::vector<SceneControl> scene_controls(const Scene& scene);

/// The scene with the controls' values in place of its own settings. An empty value keeps the
/// scene's. Throws std::invalid_argument naming the control for a value that is not one it takes
/// (a rule by another name, a non-square count for a stratified pattern, a negative index).
void apply_scene_controls(const std::map<std::string, std::string>& values, Scene& scene);

/// True when a value differs from the scene's own, so that the reference trace, recorded with the
/// scene's settings, no longer describes the render.
bool controls_change_scene(const std::map<std::string, std::string>& values, const Scene& scene);

}  // namespace raystep
