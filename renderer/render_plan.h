#pragma once

#include <vector>

#include "base/scene/scene_features.h"
#include "renderer/view.h"

namespace raystep {

/// Spheres and triangles from which the renderer builds a BVH; below, it tests every one. A BVH
/// costs less per ray from a few primitives on, but below 16 brute force costs a 640 x 480 image
/// under a tenth of a second on one thread, and in exchange every scene of a handful of
/// primitives (every scene of stages 2 and 3) renders with stages 1 to 3 alone, before stage 4
/// exists. `raystep-reference bench --threshold` measures both sides of that trade, and the
/// handout gives its figures: docs/stage4.md, "When a structure pays". Planes are unbounded and
/// always tested one by one.
inline constexpr std::size_t kBvhFromPrimitives = 16;

/// The primitives the world's BVH would hold: spheres and triangles without a transform. Those
/// under one are instances, each in its own frame, and planes are unbounded.
std::size_t bvh_primitives(const SceneFeatures& features);

/// True when the renderer builds a BVH over the world's spheres and triangles.
bool uses_bvh(const SceneFeatures& features);

/// True when the renderer builds a BVH over the instances' world boxes (from kBvhFromPrimitives
/// instances on, for the same reason), or within an instance over its own primitives: then a
/// render runs stage 4 too.
bool uses_instance_bvh(const SceneFeatures& features);

/// The stages whose code renders this view of a scene with these features, in lecture order:
/// what a render of it exercises, and so what its image can grade. Only what the scene uses
/// counts: acceleration (stage 4) only for scenes big enough to gain from it, transforms
/// (stage 5) only when an object has one, reflection (stage 7) only when a material reflects and
/// maxdepth allows a bounce; sampling (stage 8) in the shaded and full views of a scene with
/// more than one sample per pixel or a quad light (the views that average samples,
/// render_pixel.h); refraction (stage 9, and stage 7 whose reflected_ray it uses) in the full
/// view of a scene where something transmits and maxdepth allows a bounce. The full view of a
/// path-traced scene (`integrator pathtracer`) runs stage 10 instead of 7 and 9, and stage 8
/// only for more than one sample per pixel. Surface detail (stage 11) in the views that shade, of
/// a scene with a triangle that has vertex normals or an object whose material has a map, and
/// in the uv and tangent views, which show its coordinates and frames.
std::vector<int> stages_for_view(const SceneFeatures& features, View view);

}  // namespace raystep
