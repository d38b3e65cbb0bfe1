#pragma once

#include "base/math/parallel_sine.h"
#include "base/math/types.h"

namespace raystep {

// Stage 1: vector math, the language of every later stage. Handout: docs/stage1.md.
// Vec3 is glm::dvec3: use its + - * / and its components .x .y .z, and write the rest here
// yourself (GLM has dot, cross, length, normalize and reflect too; the tests compare with them).

/// a . b = ax bx + ay by + az bz.
double dot(const Vec3& a, const Vec3& b);

/// a x b: perpendicular to a and b, right-handed, of length |a| |b| sin(angle).
Vec3 cross(const Vec3& a, const Vec3& b);

/// |v|, correct to a few ulps for every finite v, including components as large as 1e200 or as
/// small as 1e-200, whose squares overflow or underflow a double.
double length(const Vec3& v);

/// v / |v|, for every finite nonzero v (tiny and huge ones too). Throws std::domain_error when v
/// is zero or has an infinite or NaN component: such a v has no direction.
Vec3 normalize(const Vec3& v);

/// The mirror image of direction d about the plane with unit normal n: d - 2 (d . n) n.
/// The length of d is kept; n must be unit length.
Vec3 reflect(const Vec3& d, const Vec3& n);

/// The projection of v onto the line along `onto`: ((v . onto) / (onto . onto)) onto, for every
/// finite nonzero `onto`, tiny and huge ones too (whose onto . onto underflows or overflows).
/// Throws std::domain_error when `onto` is zero.
Vec3 project_onto(const Vec3& v, const Vec3& onto);

/// The component of v perpendicular to `edge`: v minus its projection onto `edge`. Stage 3
/// builds the inward normal of a triangle's edge with it. Throws std::domain_error when `edge`
/// is zero.
Vec3 perpendicular_to(const Vec3& v, const Vec3& edge);

/// A right-handed orthonormal basis: u x v = w.
struct Frame {
    Vec3 u;
    Vec3 v;
    Vec3 w;
};

/// The lecture's frame from a and b: w = a / |a|, u = (b x w) / |b x w|, v = w x u.
/// For a camera, a = lookfrom - lookat and b = up, so u points right, v up, w backwards.
/// Throws std::domain_error when a or b is zero or has an infinite or NaN component (no
/// direction, as for normalize), or when b is parallel to a: when
/// |b x w| <= kParallelSine |b|, a test relative to |b|, so that a tiny b across a is a frame and
/// a huge b nearly along it is not (see base/math/parallel_sine.h for why rounding makes "exactly
/// zero" the wrong test).
Frame orthonormal_frame(const Vec3& a, const Vec3& b);

}  // namespace raystep
