#pragma once

#include <string>

#include "base/math/double_double_vec.h"
#include "base/math/types.h"
#include "stages/2_rays/ray.h"

namespace raystep::grade {

// How a case's values are written in a report, the same way for every check and for
// `raystep grade`: every digit (17 significant), so that a counterexample shows the difference,
// however small, and can be typed back in; and the one test of a value the judges share.

/// `1.0000000000000002`, `inf`.
std::string full_text(double x);

/// A double-double's nearest double, as full_text writes it: a report shows what a double answer
/// can be.
std::string full_text(const DoubleDouble& x);

/// `(1, 2.5)` and `(1, 2.5, -3)`, each coordinate as full_text writes it.
std::string full_text(const Vec2& v);
std::string full_text(const Vec3& v);

/// A 4x4 matrix row by row: `rows [a, b, c, d]; [...]; [...]; [...]`.
std::string matrix_text(const Mat4& m);

/// `origin (...), direction (...), t in [t_min, t_max]`.
std::string ray_text(const Ray& r);

/// A vector a student normalized (a camera ray's direction, a normal): its length, taken in
/// double-double (base/math/double_double.h), within 4 ulps of 1 (2^-52 each), since every
/// normalization a student may write (stage 1's, glm's, v / |v|) lands within 3. Written so that a
/// NaN fails.
bool unit_length(const Vec3& v);

/// Each coordinate of `got` within its own tolerance of the expectation's, compared in
/// double-double (a grader's oracle decided both). Written so that a NaN fails.
bool near_wide(const Vec3& got, const DoubleDoubleVec3& expected,
               const DoubleDoubleVec3& tolerance);

/// |got - expected| <= tolerance in double-double, got taken exactly. Written so that a NaN fails.
bool near_wide(double got, const DoubleDouble& expected, const DoubleDouble& tolerance);

/// |got - expected| <= tolerance in double, for a vector each coordinate: an expectation an oracle
/// rounded to double, its tolerance many ulps. Written so that a NaN fails.
bool near_double(double got, double expected, double tolerance);
bool near_double(const Vec2& got, const Vec2& expected, double tolerance);
bool near_double(const Vec3& got, const Vec3& expected, double tolerance);

}  // namespace raystep::grade
