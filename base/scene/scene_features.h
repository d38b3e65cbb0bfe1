#pragma once

#include <cstddef>

#include "base/scene/scene.h"

namespace raystep {

/// What a scene uses, counted: the facts from which the renderer decides what to build and the
/// grader decides which stages a render of it grades.
struct SceneFeatures {
    std::size_t spheres = 0;
    std::size_t triangles = 0;  ///< all triangles, mesh triangles included
    std::size_t mesh_triangles = 0;
    /// Triangles with vertex normals (`trinormal`, a mesh's `vn` or `mesh FILE smooth`, a defined
    /// mesh's once per instance), shaded by stage 11's interpolation.
    std::size_t smooth_triangles = 0;
    /// Objects whose material looks up an image (`texture`, `normalmap`, `bumpmap`): stage 11's
    /// lookups. Each sphere, plane and triangle counts (a `mesh` file's too), and each `instance`
    /// once.
    std::size_t mapped_objects = 0;
    std::size_t meshes = 0;
    std::size_t planes = 0;
    std::size_t transforms = 0;             ///< distinct non-identity transforms in use
    std::size_t transformed_objects = 0;    ///< primitives under one of them
    std::size_t transformed_spheres = 0;    ///< of those, spheres: ellipsoids
    std::size_t transformed_triangles = 0;  ///< of those, triangles
    std::size_t mesh_definitions = 0;       ///< `define`
    std::size_t mesh_instances = 0;         ///< `instance`
    std::size_t instanced_triangles = 0;    ///< the triangles they place, counted per instance
    /// Objects intersected in their own frame: the spheres and triangles under one transform
    /// together, and each mesh instance.
    std::size_t instances = 0;
    /// Spheres and triangles of the largest of those.
    std::size_t largest_instance = 0;
    std::size_t point_lights = 0;
    std::size_t directional_lights = 0;
    std::size_t spot_lights = 0;
    std::size_t quad_lights = 0;           ///< area lights: soft shadows, stage 8
    int samples_per_pixel = 1;             ///< `spp`; above 1, antialiasing by stage 8
    std::size_t reflective_objects = 0;    ///< specular > 0 with maxdepth > 0, CSE167: mirrors
    std::size_t transmissive_objects = 0;  ///< transmission > 0 with maxdepth > 0, not path-traced:
                                           ///< stage 9
    bool path_traced = false;              ///< `integrator pathtracer`: stage 10's paths

    std::size_t primitives() const { return spheres + triangles + planes; }
    bool uses_transforms() const { return transformed_objects > 0; }
    bool uses_lights() const {
        return point_lights + directional_lights + spot_lights + quad_lights > 0;
    }
    bool uses_reflection() const { return reflective_objects > 0; }
    bool uses_sampling() const { return samples_per_pixel > 1 || quad_lights > 0; }
    bool uses_refraction() const { return transmissive_objects > 0; }
    bool uses_smooth_normals() const { return smooth_triangles > 0; }
    bool uses_surface_detail() const { return smooth_triangles + mapped_objects > 0; }
};

SceneFeatures scene_features(const Scene& scene);

}  // namespace raystep
