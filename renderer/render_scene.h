#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <variant>
#include <vector>

#include "base/image/image.h"
#include "base/scene/scene.h"
#include "renderer/instance.h"
#include "renderer/instance_bvh.h"
#include "stages/2_rays/camera.h"
#include "stages/3_intersect/intersect.h"
#include "stages/4_accel/bvh.h"
#include "stages/5_transforms/transform.h"

namespace raystep {

/// The camera of a scene, perspective or orthographic, as stage 2 builds it.
using SceneCamera = std::variant<PerspectiveCamera, OrthographicCamera>;

/// The instance of a primitive without one.
inline constexpr std::uint32_t kNoInstance = 0xffffffffu;

/// The scene as the renderer uses it, built once per render by the stages: the camera from
/// stage 2; the spheres and triangles without a transform in the world for stage 3, under a BVH
/// from stage 4 when there are enough to gain from one; those under a transform as instances
/// (instance.h), grouped by transform, and each mesh instance, in their own frame for stage 5,
/// under a BVH of their own when there are enough of them; and the planes, moved into the world
/// by stage 5 (flat and unbounded, they need no frame of their own). `scene` keeps materials and
/// lights.
struct RenderScene {
    const Scene* scene = nullptr;
    SceneCamera camera;
    /// The world's spheres and triangles, in Scene order, and every plane: index k of planes is
    /// Scene's k-th, of spheres sphere_index[k], of triangles triangle_index[k].
    PrimitiveList primitives;
    std::vector<std::size_t> sphere_index;
    std::vector<std::size_t> triangle_index;
    std::optional<Bvh> bvh;  ///< over `primitives`' spheres and triangles, when uses_bvh
    PrimitiveList planes;    ///< the planes alone, tested one by one beside the BVH
    std::vector<InstanceGeometry> instance_geometries;
    /// The groups of spheres and triangles under one transform, in the order their first member
    /// is written, then the mesh instances, from first_mesh_instance on, in Scene order.
    std::vector<Instance> instances;
    std::size_t first_mesh_instance = 0;
    std::optional<InstanceBvh> instance_bvh;  ///< from kBvhFromPrimitives instances on
    /// The instance of each of Scene::spheres and Scene::triangles, kNoInstance in the world.
    std::vector<std::uint32_t> sphere_instance;
    std::vector<std::uint32_t> triangle_instance;
    RayOffset ray_offset;  ///< how shadow and mirror rays leave a surface
    /// Bounces after the eye ray's hit: maxdepth when something reflects or transmits, else 0.
    int bounces = 0;
    /// Something transmits: the full view follows stage 9's radiance_with_refraction.
    bool refraction = false;
    /// The part of each camera ray a render looks at, a near and a far clip: stage 2's rays run
    /// over [0, inf), and the grader narrows them to see that stage 4 keeps to [t_min, t_max].
    double camera_t_min = 0.0;
    double camera_t_max = std::numeric_limits<double>::infinity();
    /// Scene::textures' images, read when the scene is prepared.
    std::vector<Image> textures;
};

/// The scene's `camera` (and `ortho`) over its width x height pixels, built by stage 2, whose
/// errors and stubs propagate.
SceneCamera make_scene_camera(const Scene& scene);

/// Builds the camera with stage 2 (whose errors and stubs propagate), gathers the primitives into
/// the world's list and the instances (composing their transforms with stage 5), builds the
/// BVHs with stage 4, where there are enough primitives or instances to gain from one, and reads
/// the materials' images. Throws InputError naming the scene line of an image it cannot read.
RenderScene prepare_render_scene(const Scene& scene);

/// The nearest hit of the ray in the scene, as stage 3's closest_hit over every primitive, each in
/// its own frame, defines it (ties to the earlier primitive, spheres before triangles before
/// planes), with `index` into Scene's list of its kind (for triangles, the numbering of
/// triangle_count): through the world's BVH and the planes when there is a BVH, else closest_hit
/// itself, then the instances, through their BVH when they have one. Adds the BVHs' nodes and all
/// tests to `stats` when it is given.
std::optional<PrimitiveHit> scene_closest_hit(const RenderScene& render_scene, const Ray& ray,
                                              TraversalStats* stats);

/// True when anything in the scene meets the ray within [t_min, t_max]: a shadow ray's question.
bool scene_occluded(const RenderScene& render_scene, const Ray& ray);

/// The camera ray through the centre of pixel (i, j), from stage 2; the RenderScene's, cut to its
/// camera_t_min and camera_t_max.
Ray camera_ray(const SceneCamera& camera, int i, int j);
Ray camera_ray(const RenderScene& render_scene, int i, int j);

/// The camera ray through the point `film` of the image plane, in pixel coordinates (stage 8's
/// perspective_ray_through or orthographic_ray_through), cut like camera_ray.
Ray camera_ray_through(const RenderScene& render_scene, const Vec2& film);

/// The scene's record of a primitive the renderer hit.
const ObjectAttributes& attributes_of(const RenderScene& render_scene, PrimitiveKind kind,
                                      std::size_t index);

/// The material of a primitive the renderer hit.
const Material& material_of(const RenderScene& render_scene, const PrimitiveHit& hit);

/// The instance that places a sphere or triangle the renderer hit, nullptr for one in the world
/// (and for planes).
const Instance* instance_of(const RenderScene& render_scene, PrimitiveKind kind, std::size_t index);

/// Triangle `index` of the scene's numbering (triangle_count) as written, in its object frame.
const Triangle& triangle_shape(const RenderScene& render_scene, std::size_t index);

/// Triangle `index`'s smooth normals and texture coordinates: a scene triangle's own, or for a
/// placed mesh's triangle its definition's (MeshDefinition), indices into Scene::vertex_normals
/// and Scene::vertex_uvs, -1 for none.
struct TriangleCorners {
    std::int32_t vertex_normals = -1;
    std::int32_t vertex_uvs = -1;
};
TriangleCorners triangle_corners(const RenderScene& render_scene, std::size_t index);

/// "sphere", "triangle", "plane".
const char* kind_name(PrimitiveKind kind);

}  // namespace raystep
