#pragma once

// Stage 11 calls: every function of the contract, one value at a time. A texture travels in the
// question as a small image (image_json.h), so a lookup is judged on texels the grader chose.

#include <optional>

#include "app/probe/probe_call.h"
#include "grading/11_surface_detail/surface_detail_json.h"
#include "stages/11_surface_detail/surface_detail.h"

namespace raystep::probe {

inline constexpr auto interpolate_normal_call =
    function_call<Vec3(const Vec3&, const Vec3&, const Vec3&, double, double), &interpolate_normal>(
        "interpolate_normal");
inline constexpr auto interpolate_uv_call =
    function_call<Vec2(const Vec2&, const Vec2&, const Vec2&, double, double), &interpolate_uv>(
        "interpolate_uv");
inline constexpr auto sphere_uv_call = function_call<Vec2(const Vec3&), &sphere_uv>("sphere_uv");
inline constexpr auto surface_derivatives_call =
    function_call<std::optional<SurfaceDerivatives>(const Vec3&, const Vec3&, const Vec3&,
                                                    const Vec2&, const Vec2&, const Vec2&),
                  &surface_derivatives>("surface_derivatives");
inline constexpr auto tangent_frame_call =
    function_call<std::optional<TangentFrame>(const SurfaceDerivatives&, const Vec3&),
                  &tangent_frame>("tangent_frame");
inline constexpr auto wrap_texel_call =
    function_call<int(int, int, WrapMode), &wrap_texel>("wrap_texel");
inline constexpr auto texture_nearest_call =
    function_call<Color(const Image&, const Vec2&, WrapMode), &texture_nearest>("texture_nearest");
inline constexpr auto texture_bilinear_call =
    function_call<Color(const Image&, const Vec2&, WrapMode), &texture_bilinear>(
        "texture_bilinear");
inline constexpr auto normal_from_map_call =
    function_call<Vec3(const TangentFrame&, const Color&), &normal_from_map>("normal_from_map");
inline constexpr auto height_slopes_call =
    function_call<Vec2(const Image&, const Vec2&, WrapMode, double), &height_slopes>(
        "height_slopes");
inline constexpr auto bump_normal_call =
    function_call<Vec3(const SurfaceDerivatives&, const Vec3&, const Vec2&), &bump_normal>(
        "bump_normal");

inline constexpr auto surface_detail_calls = std::make_tuple(
    interpolate_normal_call, interpolate_uv_call, sphere_uv_call, surface_derivatives_call,
    tangent_frame_call, wrap_texel_call, texture_nearest_call, texture_bilinear_call,
    normal_from_map_call, height_slopes_call, bump_normal_call);

}  // namespace raystep::probe
