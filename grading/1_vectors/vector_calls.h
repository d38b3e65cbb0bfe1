#pragma once

// Stage 1 calls: each vector function on the vectors given, in order.

#include "app/probe/probe_call.h"
#include "stages/1_vectors/vectors.h"

namespace raystep::probe {

inline constexpr auto dot_call = function_call<double(const Vec3&, const Vec3&), &dot>("dot");
inline constexpr auto cross_call = function_call<Vec3(const Vec3&, const Vec3&), &cross>("cross");
inline constexpr auto length_call = function_call<double(const Vec3&), &length>("length");
inline constexpr auto normalize_call = function_call<Vec3(const Vec3&), &normalize>("normalize");
inline constexpr auto reflect_call =
    function_call<Vec3(const Vec3&, const Vec3&), &reflect>("reflect");
inline constexpr auto project_onto_call =
    function_call<Vec3(const Vec3&, const Vec3&), &project_onto>("project_onto");
inline constexpr auto perpendicular_to_call =
    function_call<Vec3(const Vec3&, const Vec3&), &perpendicular_to>("perpendicular_to");
inline constexpr auto orthonormal_frame_call =
    function_call<Frame(const Vec3&, const Vec3&), &orthonormal_frame>("orthonormal_frame");

inline constexpr auto vector_calls =
    std::make_tuple(dot_call, cross_call, length_call, normalize_call, reflect_call,
                    project_onto_call, perpendicular_to_call, orthonormal_frame_call);

}  // namespace raystep::probe
