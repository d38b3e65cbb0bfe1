#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace raystep {

// The whole student API is double precision: the lectures' formulas stay exact enough that a
// wrong answer is a wrong formula, not rounding. Float variants live in solutions/ where a
// speed-versus-error study needs them.

/// A point in the plane: a sample in [0, 1)^2, a position on the film in pixels.
using Vec2 = glm::dvec2;
/// A point, a direction or a normal in 3D.
using Vec3 = glm::dvec3;
/// Homogeneous coordinates, for transforms.
using Vec4 = glm::dvec4;
/// 4x4 matrix, column-major as in GLM and OpenGL.
using Mat4 = glm::dmat4;
/// Linear RGB; 1 is full intensity. Images clamp to [0, 1] only when written as 8-bit.
using Color = glm::dvec3;

}  // namespace raystep
