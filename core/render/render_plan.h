#pragma once

#include <vector>

#include "core/render/view.h"
#include "core/scene/scene_features.h"

namespace raystep {

/// Spheres and triangles from which a BVH pays for itself over a 640 x 480 image, its build
/// included: below, the renderer tests every primitive. Measured, not guessed: `raystep bench
/// --threshold` times both for scenes of 1 to 512 primitives (docs/stage4.md, "When a structure
/// pays"). Planes are unbounded and always tested one by one.
inline constexpr std::size_t kBvhFromPrimitives = 8;

/// True when the renderer builds a BVH for a scene with these features.
bool uses_bvh(const SceneFeatures& features);

/// The stages whose code renders this view of a scene with these features, in lecture order:
/// what a render of it exercises, and so what its image can grade. Only what the scene uses
/// counts: acceleration (stage 4) only for scenes big enough to gain from it, transforms
/// (stage 5) only when an object has one, reflection (stage 7) only when a material reflects and
/// maxdepth allows a bounce.
std::vector<int> stages_for_view(const SceneFeatures& features, View view);

}  // namespace raystep
