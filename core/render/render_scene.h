#pragma once

#include <cstddef>
#include <optional>
#include <variant>

#include "core/scene/scene.h"
#include "stages/2_rays/camera.h"
#include "stages/3_intersect/intersect.h"
#include "stages/4_accel/bvh.h"

namespace raystep {

/// The scene as the renderer uses it, built once per render by the stages: the camera from
/// stage 2, the primitives gathered for stage 3, and a BVH from stage 4 when the scene is big
/// enough to gain from one. `scene` keeps materials and lights.
struct RenderScene {
    const Scene* scene = nullptr;
    std::variant<PerspectiveCamera, OrthographicCamera> camera;
    PrimitiveList primitives;  ///< in Scene order, so index k of a kind is Scene's k-th of it
    std::optional<Bvh> bvh;    ///< over the spheres and triangles, when uses_bvh
    PrimitiveList planes;      ///< the planes alone, tested one by one beside the BVH
};

/// Builds the camera with stage 2 (whose errors and stubs propagate) and gathers the
/// primitives. Throws std::runtime_error for a scene that needs a capability this build lacks.
RenderScene prepare_render_scene(const Scene& scene);

/// The nearest hit of the ray in the scene, as stage 3's closest_hit over every primitive
/// defines it: through the BVH and the planes when there is a BVH, else closest_hit itself.
/// Adds the BVH's nodes and tests to `stats` when it is given.
std::optional<PrimitiveHit> scene_closest_hit(const RenderScene& render_scene, const Ray& ray,
                                              TraversalStats* stats);

/// The camera ray through the centre of pixel (i, j), from stage 2.
Ray camera_ray(const RenderScene& render_scene, int i, int j);

/// The scene's record of a primitive the renderer hit.
const ObjectAttributes& attributes_of(const RenderScene& render_scene, PrimitiveKind kind,
                                      std::size_t index);

/// "sphere", "triangle", "plane".
const char* kind_name(PrimitiveKind kind);

}  // namespace raystep
