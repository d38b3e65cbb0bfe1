#pragma once

#include <vector>

#include <CLI/CLI.hpp>

#include "base/scene/scene.h"

namespace raystep {

/// `--lookfrom X Y Z`: the scene's eye moved there, the rest of its camera kept (what it looks at,
/// the up hint, the field of view). The grader renders each scene from an eye of its own
/// (docs/student-README.md, "Grade your work before you hand it in"), and this renders or traces
/// the same view here.
void add_eye_option(CLI::App& command, std::vector<double>& lookfrom);

/// The scene with the eye the command line gives, if any. Throws std::invalid_argument when the
/// eye is the scene's look-at point, from which the camera looks nowhere.
void apply_eye(const std::vector<double>& lookfrom, Scene& scene);

}  // namespace raystep
