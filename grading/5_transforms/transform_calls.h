#pragma once

// Stage 5 calls: the three matrices, their composition, and a transformed object's rays, points,
// normals and hits.

#include <optional>
#include <vector>

#include "app/probe/probe_call.h"
#include "stages/5_transforms/transform.h"

namespace raystep::probe {

inline constexpr auto translation_call =
    function_call<Mat4(const Vec3&), &translation>("translation");
inline constexpr auto rotation_call =
    function_call<Mat4(const Vec3&, double), &rotation>("rotation");
inline constexpr auto scaling_call = function_call<Mat4(const Vec3&), &scaling>("scaling");
/// The ops are the whole question, an array of them, not an array holding one.
inline constexpr ProbeCall<std::vector<TransformOp>, Transform> compose_call{
    "compose", [](const std::vector<TransformOp>& ops) { return compose(ops); }};
inline constexpr auto ray_to_object_call =
    function_call<Ray(const Transform&, const Ray&), &ray_to_object>("ray_to_object");
inline constexpr auto point_to_world_call =
    function_call<Vec3(const Transform&, const Vec3&), &point_to_world>("point_to_world");
inline constexpr auto normal_to_world_call =
    function_call<Vec3(const Transform&, const Vec3&), &normal_to_world>("normal_to_world");
inline constexpr auto intersect_transformed_sphere_call =
    function_call<std::optional<Hit>(const Ray&, const Sphere&, const Transform&),
                  &intersect_transformed_sphere>("intersect_transformed_sphere");

inline constexpr auto transform_calls =
    std::make_tuple(translation_call, rotation_call, scaling_call, compose_call, ray_to_object_call,
                    point_to_world_call, normal_to_world_call, intersect_transformed_sphere_call);

}  // namespace raystep::probe
