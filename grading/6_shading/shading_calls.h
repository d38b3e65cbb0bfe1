#pragma once

// Stage 6 calls: lights, the local model, and rays that leave a surface.

#include <vector>

#include "app/probe/probe_call.h"
#include "stages/6_shading/shading.h"

namespace raystep::probe {

inline constexpr auto attenuation_call =
    function_call<double(const Attenuation&, double), &raystep::attenuation>("attenuation");
inline constexpr auto sample_point_light_call =
    function_call<LightSample(const PointLight&, const Vec3&), &sample_light>("sample_point_light");
inline constexpr auto sample_directional_light_call =
    function_call<LightSample(const DirectionalLight&), &sample_light>("sample_directional_light");
inline constexpr auto blinn_phong_call =
    function_call<Color(const Material&, const SurfacePoint&, const LightSample&), &blinn_phong>(
        "blinn_phong");
inline constexpr auto local_shading_call =
    function_call<Color(const Material&, const SurfacePoint&, const std::vector<LightSample>&),
                  &local_shading>("local_shading");
inline constexpr auto spawn_ray_call =
    function_call<Ray(const SurfacePoint&, const Vec3&, double, const RayOffset&), &spawn_ray>(
        "spawn_ray");
inline constexpr auto shadow_ray_call =
    function_call<Ray(const SurfacePoint&, const LightSample&, const RayOffset&), &shadow_ray>(
        "shadow_ray");

inline constexpr auto shading_calls =
    std::make_tuple(attenuation_call, sample_point_light_call, sample_directional_light_call,
                    blinn_phong_call, local_shading_call, spawn_ray_call, shadow_ray_call);

}  // namespace raystep::probe
