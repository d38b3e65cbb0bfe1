#include "base/scene/scene_features.h"

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
        if (scene.max_depth > 0 && material.specular != Color(0.0)) ++features.reflective_objects;
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
    features.planes = scene.planes.size();
    features.point_lights = scene.point_lights.size();
    features.directional_lights = scene.directional_lights.size();
    std::unordered_set<std::uint32_t> transforms;
    count_objects(scene, scene.spheres, features, transforms);
    count_objects(scene, scene.triangles, features, transforms);
    count_objects(scene, scene.planes, features, transforms);
    features.transforms = transforms.size();
    for (const SceneSphere& sphere : scene.spheres) {
        if (sphere.attributes.transform != 0) ++features.transformed_spheres;
    }
    return features;
}

}  // namespace raystep
