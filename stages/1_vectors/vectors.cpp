// Stage 1: vector math. Handout: docs/stage1.md. Replace each RAYSTEP_TODO with your code;
// run the stage's tests with `ctest --preset student -L stage1`.

#include "stages/1_vectors/vectors.h"

#include <cmath>
#include <stdexcept>

#include "base/errors/not_implemented.h"

namespace raystep {

double dot(const Vec3& a, const Vec3& b) {
    // Multiply component by component and add: a . b = ax bx + ay by + az bz.
    RAYSTEP_TODO(1, "dot", "Dot product");
}

Vec3 cross(const Vec3& a, const Vec3& b) {
    // The determinant with rows (x y z), a, b:
    // (ay bz - az by, az bx - ax bz, ax by - ay bx).
    RAYSTEP_TODO(1, "cross", "Cross product");
}

double length(const Vec3& v) {
    // sqrt(v . v) is the formula, but v . v overflows for components near 1e200 and underflows
    // to 0 near 1e-200. Divide by the largest |component| m first, then multiply back:
    // |v| = m |v / m|.
    RAYSTEP_TODO(1, "length", "Length without overflow");
}

Vec3 normalize(const Vec3& v) {
    // v / |v|. A zero or non-finite v has no direction: throw std::domain_error, never return
    // NaN (a NaN direction silently turns whole images black).
    RAYSTEP_TODO(1, "normalize", "Normalizing");
}

Vec3 reflect(const Vec3& d, const Vec3& n) {
    // Remove the component of d along n twice: d - 2 (d . n) n, for a unit normal n.
    RAYSTEP_TODO(1, "reflect", "Reflection");
}

Vec3 project_onto(const Vec3& v, const Vec3& onto) {
    // The part of v along `onto`: (v . o^) o^ with o^ = onto / |onto|, which works for tiny and
    // huge `onto` too (onto . onto would underflow or overflow). Throw std::domain_error for a
    // zero `onto`.
    RAYSTEP_TODO(1, "project_onto", "Projection");
}

Vec3 perpendicular_to(const Vec3& v, const Vec3& edge) {
    // What is left of v once its projection onto the edge is taken away.
    RAYSTEP_TODO(1, "perpendicular_to", "Projection");
}

Frame orthonormal_frame(const Vec3& a, const Vec3& b) {
    // w = a / |a|, u = (b x w) / |b x w|, v = w x u. Throw std::domain_error when a or b is zero
    // or when |b x w| <= kParallelSine |b|: then b and a are parallel and u has no direction.
    RAYSTEP_TODO(1, "orthonormal_frame", "Orthonormal frames");
}

}  // namespace raystep
