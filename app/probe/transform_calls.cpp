// Stage 5 calls: the matrices, the stack's product, and moving rays, points and normals between
// frames.

#include "app/probe/call_table.h"
#include "stages/5_transforms/transform.h"

namespace raystep::probe {

void add_transform_calls(CallTable& table) {
    table["translation"] = [](const Json& a) { return mat4(translation(vec3_from(a.at(0)))); };
    table["rotation"] = [](const Json& a) {
        return mat4(rotation(vec3_from(a.at(0)), number_from(a.at(1))));
    };
    table["scaling"] = [](const Json& a) { return mat4(scaling(vec3_from(a.at(0)))); };
    table["compose"] = [](const Json& a) {
        std::vector<TransformOp> ops;
        for (const Json& op : a)
            ops.push_back(transform_op_from(op));
        return transform(compose(ops));
    };
    table["ray_to_object"] = [](const Json& a) {
        return ray(ray_to_object(transform_from(a.at(0)), ray_from(a.at(1))));
    };
    table["point_to_world"] = [](const Json& a) {
        return vec3(point_to_world(transform_from(a.at(0)), vec3_from(a.at(1))));
    };
    table["normal_to_world"] = [](const Json& a) {
        return vec3(normal_to_world(transform_from(a.at(0)), vec3_from(a.at(1))));
    };
    table["intersect_transformed_sphere"] = [](const Json& a) {
        return hit(intersect_transformed_sphere(ray_from(a.at(0)), sphere_from(a.at(1)),
                                                transform_from(a.at(2))));
    };
}

}  // namespace raystep::probe
