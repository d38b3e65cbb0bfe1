#pragma once

#include <filesystem>
#include <vector>

#include "studies/epsilon/epsilon_study.h"

namespace raystep {

/// The study on one scene, through this program's stages (surface points, shadow rays, the
/// scene's closest hit and occlusion): every pixel of the scene's image, every point light, every
/// rule, and each epsilon for the fixed rules. A stub or an error stops it and is recorded in
/// `stopped`. Throws std::invalid_argument for a scene the exact answer does not model (a
/// transform) or that has no point light.
EpsilonSceneResult measure_epsilon_scene(const std::filesystem::path& scene,
                                         const std::vector<double>& epsilons);

}  // namespace raystep
