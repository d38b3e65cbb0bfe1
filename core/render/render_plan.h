#pragma once

#include <vector>

#include "core/render/view.h"
#include "core/scene/scene_features.h"

namespace raystep {

/// The stages whose code renders this view of a scene with these features, in lecture order:
/// what a render of it exercises, and so what its image can grade. Only what the scene uses
/// counts: transforms (stage 5) only when an object has one, reflection (stage 7) only when a
/// material reflects and maxdepth allows a bounce.
std::vector<int> stages_for_view(const SceneFeatures& features, View view);

}  // namespace raystep
