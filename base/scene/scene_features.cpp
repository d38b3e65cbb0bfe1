#include "base/scene/scene_features.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace raystep {

namespace {

template <class Object>
void count_objects(const Scene& scene, const std::vector<Object>& objects, SceneFeatures& features,
                   std::unordered_set<std::uint32_t>& transforms) {
    for (const Object& object : objects) {
        if (object.attributes.transform != 0) {
            ++features.transformed_objects;
            transforms.insert(object.attributes.transform);
        }
        const Material& material = scene.materials[object.attributes.material];
        // Mirrors and dielectrics need a secondary ray, which maxdepth 0 turns off; in the
        // CSE168 dialect specular is a glossy lobe, not a mirror.
        if (scene.max_depth == 0) continue;
        if (material.specular != Color(0.0) && scene.dialect == SceneDialect::cse167)
            ++features.reflective_objects;
        // The path tracer neither mirrors nor refracts.
        if (material.transmission != Color(0.0) && scene.integrator != Integrator::pathtracer)
            ++features.transmissive_objects;
    }
}

}  // namespace

SceneFeatures scene_features(const Scene& scene) {
    SceneFeatures features;
    features.spheres = scene.spheres.size();
    features.triangles = scene.triangles.size();
    features.meshes = scene.meshes.size();
    for (const SceneMesh& mesh : scene.meshes)
        features.mesh_triangles += mesh.triangle_count;
    for (const SceneTriangle& triangle : scene.triangles) {
        if (triangle.vertex_normals >= 0) ++features.smooth_triangles;
    }
    for (const MeshInstance& instance : scene.mesh_instances) {
        const std::vector<std::int32_t>& normals =
            scene.mesh_definitions[instance.definition].vertex_normals;
        features.smooth_triangles += static_cast<std::size_t>(
            std::count_if(normals.begin(), normals.end(), [](std::int32_t n) { return n >= 0; }));
    }
    const auto mapped = [&](const ObjectAttributes& attributes) {
        return scene.materials[attributes.material].has_maps() ? 1 : 0;
    };
    for (const SceneSphere& sphere : scene.spheres)
        features.mapped_objects += mapped(sphere.attributes);
    for (const SceneTriangle& triangle : scene.triangles)
        features.mapped_objects += mapped(triangle.attributes);
    for (const ScenePlane& plane : scene.planes)
        features.mapped_objects += mapped(plane.attributes);
    for (const MeshInstance& instance : scene.mesh_instances)
        features.mapped_objects += mapped(instance.attributes);
    features.planes = scene.planes.size();
    features.point_lights = scene.point_lights.size();
    features.directional_lights = scene.directional_lights.size();
    features.spot_lights = scene.spot_lights.size();
    features.quad_lights = scene.quad_lights.size();
    features.samples_per_pixel = scene.samples_per_pixel;
    features.path_traced = scene.integrator == Integrator::pathtracer;
    std::unordered_set<std::uint32_t> transforms;
    count_objects(scene, scene.spheres, features, transforms);
    count_objects(scene, scene.triangles, features, transforms);
    count_objects(scene, scene.planes, features, transforms);
    count_objects(scene, scene.mesh_instances, features, transforms);
    features.transforms = transforms.size();

    // The renderer's instances: spheres and triangles grouped by their transform, then each
    // mesh instance.
    std::unordered_map<std::uint32_t, std::size_t> group_sizes;
    for (const SceneSphere& sphere : scene.spheres) {
        if (sphere.attributes.transform == 0) continue;
        ++features.transformed_spheres;
        ++group_sizes[sphere.attributes.transform];
    }
    for (const SceneTriangle& triangle : scene.triangles) {
        if (triangle.attributes.transform == 0) continue;
        ++features.transformed_triangles;
        ++group_sizes[triangle.attributes.transform];
    }
    features.instances = group_sizes.size();
    for (const auto& [node, size] : group_sizes)
        features.largest_instance = std::max(features.largest_instance, size);

    features.mesh_definitions = scene.mesh_definitions.size();
    features.mesh_instances = scene.mesh_instances.size();
    features.instances += scene.mesh_instances.size();
    for (const MeshInstance& instance : scene.mesh_instances) {
        const std::size_t size = scene.mesh_definitions[instance.definition].triangles.size();
        features.instanced_triangles += size;
        features.largest_instance = std::max(features.largest_instance, size);
    }
    return features;
}

}  // namespace raystep
