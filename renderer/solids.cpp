#include "renderer/solids.h"

#include <stdexcept>

#include <glm/geometric.hpp>

namespace raystep {

std::uint32_t solid_of(const RenderScene& render_scene, PrimitiveKind kind, std::size_t index) {
    const Scene& scene = *render_scene.scene;
    const std::size_t spheres = scene.spheres.size();
    const std::size_t meshes = scene.meshes.size();
    const std::size_t mesh_instances = scene.mesh_instances.size();
    const std::size_t materials = scene.materials.size();
    std::size_t solid = 0;
    switch (kind) {
        case PrimitiveKind::sphere:
            solid = index;
            break;
        case PrimitiveKind::plane:
            solid = spheres + meshes + mesh_instances + materials + index;
            break;
        case PrimitiveKind::triangle:
            if (index >= scene.triangles.size()) {
                // A mesh instance's triangle: its instance's place among the mesh instances
                const Instance* instance = instance_of(render_scene, kind, index);
                const Instance* first = &render_scene.instances[render_scene.first_mesh_instance];
                solid = spheres + meshes + static_cast<std::size_t>(instance - first);
            } else if (scene.triangles[index].mesh >= 0) {
                solid = spheres + static_cast<std::size_t>(scene.triangles[index].mesh);
            } else {
                solid =
                    spheres + meshes + mesh_instances + scene.triangles[index].attributes.material;
            }
            break;
    }
    if (solid > 0xffffffffu) throw std::out_of_range("solid_of: more solids than 2^32");
    return static_cast<std::uint32_t>(solid);
}

Medium medium_of(const RenderScene& render_scene, const PrimitiveHit& hit) {
    return {solid_of(render_scene, hit.kind, hit.index), material_of(render_scene, hit).index};
}

bool entering(const Ray& ray, const PrimitiveHit& hit) {
    return glm::dot(ray.direction, hit.hit.normal) < 0.0;
}

}  // namespace raystep
