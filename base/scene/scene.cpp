#include "base/scene/scene.h"

#include <algorithm>
#include <string>

namespace raystep {

std::size_t triangle_count(const Scene& scene) {
    std::size_t count = scene.triangles.size();
    for (const MeshInstance& instance : scene.mesh_instances) {
        count += scene.mesh_definitions[instance.definition].triangles.size();
    }
    return count;
}

std::vector<TransformOp> transform_ops(const Scene& scene, std::uint32_t node) {
    std::vector<TransformOp> ops;
    while (node != 0) {
        ops.push_back(scene.transforms.at(node).op);
        node = scene.transforms[node].parent;
    }
    std::reverse(ops.begin(), ops.end());
    return ops;
}

std::string warning_text(const Scene& scene, const SceneNote& note) {
    return scene.path + ":" + std::to_string(note.line) + ": warning: " + note.text;
}

}  // namespace raystep
