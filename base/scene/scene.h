#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/image/wrap_mode.h"
#include "base/math/types.h"
#include "base/scene/ray_offset.h"
#include "base/scene/sample_pattern.h"
#include "base/scene/shapes.h"

namespace raystep {

// The scene as the file describes it, before any rendering decision: what the loader reads and
// `raystep info` reports. Nothing here is precomputed for speed; the renderer builds what a
// scene needs from it. docs/scene-format.md gives the commands.

/// Surface properties of the CSE167 local model, I = A + E + sum of lights (D, S, shininess),
/// with S also the mirror reflectance; a material with a transmission colour is the surface of a
/// dielectric solid of index `index` (stage 9).
/// `brdf`: the CSE168 course's two BRDFs (docs/stage10.md, "The BRDF"). Its path tracer shades
/// by them; CSE167's ray tracer takes every surface as stage 6's local model.
enum class BrdfModel { phong, ggx };

struct Material {
    Color ambient{0.2, 0.2, 0.2};
    Color diffuse{0.0, 0.0, 0.0};
    Color specular{0.0, 0.0, 0.0};
    Color emission{0.0, 0.0, 0.0};
    double shininess = 0.0;
    Color transmission{0.0, 0.0, 0.0};  ///< `transmission`: Kt, black for an opaque surface
    double index = 1.0;                 ///< `ior`: index of refraction of the solid inside
    BrdfModel brdf = BrdfModel::phong;  ///< `brdf`
    double roughness = 0.0;             ///< `roughness`: GGX's alpha
    /// Images looked up at a hit's (u, v) (docs/stage11.md), indexes into Scene::textures, -1 for
    /// none: the diffuse colour is Kd times `diffuse_map`'s (`texture`); `normal_map`
    /// (`normalmap`) or `bump_map` (`bumpmap`, its heights times `bump_scale`) tilts the normal
    /// that shades.
    std::int32_t diffuse_map = -1;
    std::int32_t normal_map = -1;
    std::int32_t bump_map = -1;
    double bump_scale = 0.0;

    bool has_maps() const { return diffuse_map >= 0 || normal_map >= 0 || bump_map >= 0; }

    bool operator==(const Material& other) const {
        return ambient == other.ambient && diffuse == other.diffuse && specular == other.specular &&
               emission == other.emission && shininess == other.shininess &&
               transmission == other.transmission && index == other.index && brdf == other.brdf &&
               roughness == other.roughness && diffuse_map == other.diffuse_map &&
               normal_map == other.normal_map && bump_map == other.bump_map &&
               bump_scale == other.bump_scale;
    }
};

/// An image file that materials look up (`texture`, `normalmap`, `bumpmap`): read by the
/// renderer, not by the loader, which only checks that the file is there.
struct SceneTexture {
    std::string path;  ///< as resolved against the scene file's folder
    WrapMode wrap = WrapMode::repeat;
    std::uint32_t line = 0;  ///< the first line that named it
};

/// One command of the transform stack, kept as written so that stage 5 can build the matrix.
struct TransformOp {
    enum class Kind { translate, rotate, scale };
    Kind kind;
    Vec3 vector;               ///< offset, rotation axis or scale factors
    double angle_degrees = 0;  ///< rotate only
};

/// The transform stack as a tree: every translate, rotate or scale adds a node whose parent is
/// the node in force before it, so the transform of an object is the chain of ops from the root
/// to its node, right-multiplied in file order as in OpenGL: M = op1 op2 ... opN, and the last
/// op written is the first applied to the object. Scene::transforms[0] is the root, the
/// identity; each object stores its node. A tree (not a list of ops per object) keeps memory
/// linear in the file's length however deep the stack or long the chains.
struct TransformNode {
    std::uint32_t parent = 0;  ///< the node this op right-multiplies; the root's is itself
    TransformOp op{TransformOp::Kind::translate, Vec3(0.0), 0.0};
    bool identity = true;  ///< this node's whole chain changes nothing
};

/// Where an object came from and how it is placed and shaded.
struct ObjectAttributes {
    std::uint32_t material = 0;   ///< index into Scene::materials
    std::uint32_t transform = 0;  ///< node in Scene::transforms; 0 (the root) is the identity
    std::uint32_t line = 0;       ///< the line of the scene file that made it
};

struct SceneSphere {
    Sphere shape;
    ObjectAttributes attributes;
};

/// A triangle from `tri`, `trinormal`, `triuv` or a mesh. `vertex_normals` indexes
/// Scene::vertex_normals for smooth triangles (`trinormal`, a mesh's normals) and is -1
/// otherwise; `vertex_uvs` indexes Scene::vertex_uvs for triangles with texture coordinates
/// (`triuv`, a mesh's `vt`) and is -1 otherwise, where (u, v) is the hit's (beta, gamma); `mesh`
/// indexes Scene::meshes for mesh triangles and is -1 otherwise.
struct SceneTriangle {
    Triangle shape;
    ObjectAttributes attributes;
    std::int32_t vertex_normals = -1;
    std::int32_t vertex_uvs = -1;
    std::int32_t mesh = -1;
};

struct ScenePlane {
    Plane shape;
    ObjectAttributes attributes;
};

/// Per-vertex normals of a `trinormal` triangle, as written (not normalized).
struct VertexNormals {
    Vec3 n0;
    Vec3 n1;
    Vec3 n2;
};

/// Per-vertex texture coordinates of a triangle (`triuv`, or a mesh's `vt`).
struct VertexUvs {
    Vec2 uv0;
    Vec2 uv1;
    Vec2 uv2;
};

/// A mesh file loaded by `mesh FILE`; its triangles are in Scene::triangles.
struct SceneMesh {
    std::string path;  ///< as resolved against the scene file's folder
    std::uint32_t first_triangle = 0;
    std::uint32_t triangle_count = 0;
    std::uint32_t line = 0;
};

/// `define NAME FILE`: a mesh loaded once under a name, in its own (object) coordinates. It
/// draws nothing until `instance NAME` places it.
struct MeshDefinition {
    std::string name;
    std::string path;  ///< as resolved against the scene file's folder
    std::vector<Triangle> triangles;
    /// Each triangle's smooth normals and texture coordinates, as a mesh's triangles have them
    /// (SceneTriangle): indices into Scene::vertex_normals and Scene::vertex_uvs, -1 for none;
    /// one entry per triangle, shared by every instance.
    std::vector<std::int32_t> vertex_normals;
    std::vector<std::int32_t> vertex_uvs;
    std::uint32_t line = 0;
};

/// `instance NAME`: a defined mesh placed under the transform and material in force. Its
/// triangles are not copied; every instance of a definition shares them.
struct MeshInstance {
    std::uint32_t definition = 0;  ///< index into Scene::mesh_definitions
    ObjectAttributes attributes;
};

/// Light falls off as 1 / (constant + linear d + quadratic d^2) with distance d.
struct Attenuation {
    double constant = 1.0;
    double linear = 0.0;
    double quadratic = 0.0;
};

/// `point x y z r g b`, in world coordinates, with the attenuation in force when it was read.
struct PointLight {
    Vec3 position;
    Color color;
    Attenuation attenuation;
    std::uint32_t line = 0;
};

/// `directional x y z r g b`: light from the direction (x, y, z) (pointing towards the light),
/// in world coordinates; never attenuated.
struct DirectionalLight {
    Vec3 direction;
    Color color;
    std::uint32_t line = 0;
};

/// `spot x y z dx dy dz cutoff exponent r g b`: a point light shining along (dx, dy, dz), with
/// the attenuation in force, whose colour is scaled by cos(angle)^exponent within `cutoff`
/// degrees of its axis and is zero beyond.
struct SpotLight {
    Vec3 position;
    Vec3 direction;
    double cutoff_degrees = 0;
    double exponent = 0;
    Color color;
    Attenuation attenuation;
    std::uint32_t line = 0;
};

/// `quadLight ax ay az abx aby abz acx acy acz r g b` (the CSE168 command): the parallelogram
/// a + s ab + t ac, s and t in [0, 1], emitting radiance `radiance` from its side that
/// ac x ab points to. In world coordinates. It lights the scene; in the CSE168 dialect it is also
/// seen, as that course draws it.
struct QuadLight {
    Vec3 corner;  ///< a
    Vec3 edge1;   ///< ab
    Vec3 edge2;   ///< ac
    Color radiance;
    std::uint32_t line = 0;
};

/// A command that was read and checked but does not render as its author may expect: a setting
/// of the CSE168 path tracer that raystep has no use for (`russianroulette on`: raystep traces
/// no indirect paths), or one it adapted (a non-square `spp`, sampled at random). Nothing in a
/// scene is skipped silently: the commands that load a scene show each note as a warning.
struct SceneNote {
    std::uint32_t line = 0;
    std::string command;  ///< the command's name, as the file writes it
    std::string text;     ///< what raystep does with it
};

/// The view window of `ortho l r b t`, in the camera's (u, v) plane.
struct OrthoWindow {
    double left;
    double right;
    double bottom;
    double top;
};

/// `camera` (and `ortho`): the eye, what it looks at, the up hint, the vertical field of view.
/// With `ortho` the projection is orthographic over that window and fovy is unused.
struct CameraSpec {
    Vec3 lookfrom;
    Vec3 lookat;
    Vec3 up;
    double fovy_degrees = 0;
    std::optional<OrthoWindow> ortho;
    std::uint32_t line = 0;
};

/// Which course's meaning a scene's commands take (docs/scene-format.md, "Dialects"). The two
/// courses write the same commands and read some of them differently: CSE167's ray tracer gives
/// every material an ambient of 0.2 and traces `specular` as a mirror to `maxdepth`; the CSE168
/// path tracer's direct and path-traced integrators have no ambient, take specular as a glossy
/// lobe with no mirror ray, draw their quad lights, and read `maxdepth -1` as no limit.
enum class SceneDialect {
    cse167,  ///< the default
    cse168,  ///< a scene whose `integrator` is direct, analyticdirect or pathtracer
};

/// `integrator`: how the CSE168 path tracer renders a scene. raytracer, the default, is CSE167's
/// ray tracer; the others read the scene in the CSE168 dialect: direct samples the lights, as
/// stage 8 does; analyticdirect integrates each quad light exactly, unshadowed, as that
/// integrator does; pathtracer renders by stage 10's paths (renderer/path_traced.h).
enum class Integrator { raytracer, direct, analyticdirect, pathtracer };

/// `importancesampling`: how the path tracer draws a path's next direction (docs/stage10.md).
enum class DirectionSampling { hemisphere, cosine, brdf };

/// `nexteventestimation`: how the path tracer reaches the lights.
enum class NextEvent {
    off,  ///< only by hitting them
    on,   ///< only by sampling them (one sample per light at each hit)
    mis,  ///< both, each weighted by the power heuristic against the other
};

/// `maxdepth -1` in the CSE168 dialect: paths have no depth limit and end by Russian roulette.
inline constexpr int kUnboundedDepth = -1;

/// The bounces after which the path tracer ends a path of `maxdepth -1` that Russian roulette has
/// not ended: where a material reflects all the light it gets (Kd + Ks of 1 in a channel), the
/// roulette never ends its paths, and in a closed room a path would go on forever. In a scene
/// that reflects at most 0.9, a path's weight after 1000 bounces is below 1e-45; the loader
/// notes the scenes where it is not.
inline constexpr int kLongestPath = 1000;

/// The bounces a ray tracer without Russian roulette follows where the scene sets no limit
/// (`maxdepth -1`): the default depth of both courses.
inline constexpr int kDefaultDepth = 5;

struct Scene {
    std::string path;  ///< the scene file, as given
    SceneDialect dialect = SceneDialect::cse167;
    Integrator integrator = Integrator::raytracer;
    int width = 640;  ///< `size`
    int height = 480;
    int max_depth = kDefaultDepth;  ///< `maxdepth`: bounces after the first hit, or kUnboundedDepth
    std::string output;             ///< `output`; empty when the file names none
    CameraSpec camera;
    RayOffset ray_offset;  ///< `rayoffset`

    std::vector<Material> materials;
    std::vector<TransformNode> transforms{TransformNode{}};

    std::vector<SceneSphere> spheres;
    std::vector<SceneTriangle> triangles;
    std::vector<ScenePlane> planes;
    std::vector<SceneMesh> meshes;
    std::vector<VertexNormals> vertex_normals;
    std::vector<VertexUvs> vertex_uvs;
    std::vector<SceneTexture> textures;
    std::vector<MeshDefinition> mesh_definitions;
    std::vector<MeshInstance> mesh_instances;

    std::vector<PointLight> point_lights;
    std::vector<DirectionalLight> directional_lights;
    std::vector<SpotLight> spot_lights;
    std::vector<QuadLight> quad_lights;

    Color background{0.0, 0.0, 0.0};  ///< `background`: what a ray that leaves the scene sees
    int samples_per_pixel = 1;        ///< `spp`
    SamplePattern pixel_sampling = SamplePattern::jittered;  ///< `pixelsampling`
    int light_samples = 1;                                   ///< `lightsamples`, per quad light
    bool light_stratify = false;                             ///< `lightstratify on`
    std::uint64_t seed = 0;                                  ///< `seed`: the render's random seed
    bool schlick_fresnel = false;  ///< `fresnel schlick`; exact by default
    /// The path tracer's (`integrator pathtracer`) settings, with the CSE168 course's defaults.
    DirectionSampling importance_sampling = DirectionSampling::hemisphere;
    NextEvent next_event = NextEvent::off;
    bool russian_roulette = false;  ///< `russianroulette on`

    std::vector<SceneNote> notes;  ///< in file order, one per command name at most
};

/// The most samples `spp` and `lightsamples` may ask for, in a scene file or from the page of
/// `raystep view`: each sample is at least a ray per pixel or per light and pixel, so 2^16 of them
/// at 640 x 480 is already 2 x 10^10 rays.
inline constexpr int kMaxSamples = 1 << 16;

/// Every triangle of the scene in one numbering, the one hits use: Scene::triangles first, then
/// the triangles of each mesh instance, instance after instance in the order they were written.
std::size_t triangle_count(const Scene& scene);

/// A note as a warning line, `file:line: warning: text`, for a terminal or a log.
std::string warning_text(const Scene& scene, const SceneNote& note);

/// The ops of a transform node, root first: the order they were written in the file.
std::vector<TransformOp> transform_ops(const Scene& scene, std::uint32_t node);

}  // namespace raystep
