#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_map>
#include <variant>
#include <vector>

#include "base/scene/scene.h"
#include "stages/2_rays/camera.h"
#include "stages/3_intersect/intersect.h"
#include "stages/4_accel/bvh.h"
#include "stages/5_transforms/transform.h"

namespace raystep {

/// The camera of a scene, perspective or orthographic, as stage 2 builds it.
using SceneCamera = std::variant<PerspectiveCamera, OrthographicCamera>;

/// A sphere under a transform: an ellipsoid, intersected in its own frame by stage 5.
struct TransformedSphere {
    Sphere sphere;  ///< as written, in its object frame
    Transform transform;
    std::size_t index;  ///< in Scene::spheres
    /// The largest entry of M^-1 M - I as computed: how far the frame the intersection sees
    /// (through M^-1) and the one points come back through (M) disagree, for error bounds.
    double inverse_residual;
};

/// The scene as the renderer uses it, built once per render by the stages: the camera from
/// stage 2, the primitives in world coordinates for stage 3 (those under a transform moved there
/// by stage 5, except spheres, which become ellipsoids), and a BVH from stage 4 when the scene is
/// big enough to gain from one. `scene` keeps materials and lights.
struct RenderScene {
    const Scene* scene = nullptr;
    SceneCamera camera;
    /// Spheres without a transform, every triangle and plane, in Scene order: index k of
    /// triangles and planes is Scene's k-th, of spheres sphere_index[k].
    PrimitiveList primitives;
    std::vector<std::size_t> sphere_index;
    std::vector<TransformedSphere> transformed_spheres;
    /// For each of Scene's spheres, its place in primitives.spheres or, under a transform, in
    /// transformed_spheres.
    std::vector<std::size_t> sphere_slot;
    /// The transforms in use, by node of Scene::transforms; none for objects without one.
    std::unordered_map<std::uint32_t, Transform> transforms;
    std::optional<Bvh> bvh;  ///< over `primitives`' spheres and triangles, when uses_bvh
    PrimitiveList planes;    ///< the planes alone, tested one by one beside the BVH
    RayOffset ray_offset;    ///< how shadow and mirror rays leave a surface
    int bounces = 0;         ///< mirror bounces: maxdepth when something reflects, else 0
    /// The part of each camera ray a render looks at, a near and a far clip: stage 2's rays run
    /// over [0, inf), and the grader narrows them to see that stage 4 keeps to [t_min, t_max].
    double camera_t_min = 0.0;
    double camera_t_max = std::numeric_limits<double>::infinity();
};

/// The scene's `camera` (and `ortho`) over its width x height pixels, built by stage 2, whose
/// errors and stubs propagate.
SceneCamera make_scene_camera(const Scene& scene);

/// Builds the camera with stage 2 (whose errors and stubs propagate) and gathers the
/// primitives, moved into the world by stage 5 where a transform places them.
RenderScene prepare_render_scene(const Scene& scene);

/// The nearest hit of the ray in the scene, as stage 3's closest_hit over every primitive
/// defines it (ties to the earlier primitive, spheres before triangles before planes), with
/// `index` into Scene's list of its kind: through the BVH, the planes and the ellipsoids when
/// there is a BVH, else closest_hit itself and the ellipsoids. Adds the BVH's nodes and all tests
/// to `stats` when it is given.
std::optional<PrimitiveHit> scene_closest_hit(const RenderScene& render_scene, const Ray& ray,
                                              TraversalStats* stats);

/// True when anything in the scene meets the ray within [t_min, t_max]: a shadow ray's question.
bool scene_occluded(const RenderScene& render_scene, const Ray& ray);

/// The camera ray through the centre of pixel (i, j), from stage 2; the RenderScene's, cut to its
/// camera_t_min and camera_t_max.
Ray camera_ray(const SceneCamera& camera, int i, int j);
Ray camera_ray(const RenderScene& render_scene, int i, int j);

/// The scene's record of a primitive the renderer hit.
const ObjectAttributes& attributes_of(const RenderScene& render_scene, PrimitiveKind kind,
                                      std::size_t index);

/// "sphere", "triangle", "plane".
const char* kind_name(PrimitiveKind kind);

}  // namespace raystep
