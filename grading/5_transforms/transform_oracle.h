#pragma once

// Stage 5's expectations in long double: the op matrices and their products, the moves between
// frames, and a ray against a transformed sphere, each with how far a right implementation in
// double may land from it. No CGAL: these are products and roots, 11 bits beyond a double.

#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "base/scene/scene.h"
#include "base/scene/shapes.h"
#include "grader/oracle/wide_vec.h"
#include "stages/2_rays/ray.h"
#include "stages/5_transforms/transform.h"

namespace raystep {

using WideVec4 = glm::vec<4, Wide>;

/// The op matrices: T(offset), S(factors), and R(axis, degrees) by Rodrigues,
/// c I + (1 - c) a a^T + s [a]x with a the unit axis (a long double squares an axis of 1e-200).
WideMat wide_translation(const WideVec& offset);
WideMat wide_scaling(const WideVec& factors);
WideMat wide_rotation(const Vec3& axis, Wide degrees);

/// An op's matrix, its inverse in closed form, and the sizes its entries round at: a rotation's
/// entries are off by a few ulps of 1 and of the angle in radians, wherever they are near 0.
struct WideOp {
    WideMat matrix;
    WideMat inverse;
    WideMat size;
    WideMat inverse_size;
};

/// The op's matrices and sizes.
WideOp wide_op(const TransformOp& op);

/// M = M1 ... Mn and M^-1 = Mn^-1 ... M1^-1, and the tolerance of each entry: a product of n
/// matrices rounds each entry by about n ulps of the same product taken over the entries'
/// sizes, whatever the order of the multiplications.
struct WideTransform {
    WideMat matrix;
    WideMat inverse;
    WideMat matrix_tolerance;
    WideMat inverse_tolerance;
};

/// The ops composed in file order, M = M1 ... Mn, with the tolerances above.
WideTransform wide_compose(const std::vector<TransformOp>& ops);

/// The transform the probe gets: the long double products, each rounded once.
Transform transform_of(const std::vector<TransformOp>& ops);

/// M v in long double, v = (x, y, z, w), and the size of the terms each coordinate sums.
struct WideProduct {
    WideVec value;
    WideVec size;
};

/// M (x, y, z, w) for v = (x, y, z): a point with w = 1, a direction with w = 0.
WideProduct wide_product(const Mat4& m, const Vec3& v, double w);

/// M^-T n normalized, and how far rounding may move it: each coordinate of M^-T n by a few ulps
/// of its terms, relative to the length it is divided by.
struct WideNormal {
    WideVec value;
    WideVec tolerance;
};

/// The normal n moved by the inverse's transpose and normalized: (M^-1)^T n / |(M^-1)^T n|.
WideNormal wide_normal(const Mat4& inverse, const WideVec& n);

/// The world ray against the sphere under M, solved in long double in the object frame: t, and
/// the normal M^-T (p - C). The tolerances follow the rounding of the object-frame ray (a few
/// ulps of the terms of M^-1 A and M^-1 D), magnified along the ray by 1 / cos of the angle of
/// incidence, and for the normal by the condition of M's linear part.
struct TransformedSphereHit {
    bool hit = false;
    double t = 0.0;
    double t_tolerance = 0.0;
    WideNormal normal;
};

/// The world ray against the sphere under t, solved in long double in the object frame; no hit
/// (hit false) when neither root lies in [ray.t_min, ray.t_max].
TransformedSphereHit wide_transformed_hit(const Ray& ray, const Sphere& sphere, const Transform& t);

}  // namespace raystep
