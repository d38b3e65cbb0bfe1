#include "base/scene/scene.h"

#include <algorithm>

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

}  // namespace raystep
