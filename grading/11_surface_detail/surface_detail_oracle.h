#pragma once

#include <optional>
#include <stdexcept>

#include "base/image/image.h"
#include "base/image/wrap_mode.h"
#include "base/math/types.h"
#include "stages/11_surface_detail/surface_detail.h"

namespace raystep::grade {

// Stage 11's oracle (surface_detail_oracle.cpp): each function of the contract in long double,
// written from the contract's words rather than the reference's code, with the distance a right
// formula in double may land from it. Each tolerance is a first-order bound on a double
// formula's rounding, from the sizes of its inputs and the conditioning of its last step (a
// normalization, a quotient by a determinant), times a margin of 2 to 4; any right order of the
// same operations lands inside it, and the contract's mistakes (barycentrics swapped, v
// flipped, a frame not orthogonalized) land orders of magnitude outside. Where a case sits
// within rounding of a decision (a zero length, a texel's edge, a side), two right answers may
// differ, and the oracle throws IllConditioned: the case makers draw another.
//
// The cases whose answer is an exact zero (normals that cancel, uvs of no area, dp/du along the
// normal) are built from small dyadic numbers, on which every order of the operations is exact.

/// A case on which right answers may disagree: no expectation holds for it.
struct IllConditioned : std::logic_error {
    using std::logic_error::logic_error;
};

/// An expected value, each component to within `tolerance` (absolute).
template <class T>
struct Expected {
    T value{};
    double tolerance = 0;
};

/// interpolate_normal; nullopt where the sum is exactly zero (the function throws).
std::optional<Expected<Vec3>> expected_interpolate_normal(const Vec3& n0, const Vec3& n1,
                                                          const Vec3& n2, double beta,
                                                          double gamma);
Expected<Vec2> expected_interpolate_uv(const Vec2& uv0, const Vec2& uv1, const Vec2& uv2,
                                       double beta, double gamma);
/// sphere_uv of a unit normal; IllConditioned on the seam (n.x = 0, n.z < 0) and at the poles,
/// where a right answer's u is either end or any.
Expected<Vec2> expected_sphere_uv(const Vec3& normal);
Expected<std::optional<SurfaceDerivatives>> expected_surface_derivatives(
    const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec2& uv0, const Vec2& uv1,
    const Vec2& uv2);
Expected<std::optional<TangentFrame>> expected_tangent_frame(const SurfaceDerivatives& derivatives,
                                                             const Vec3& normal);
int expected_wrap_texel(int i, int size, WrapMode wrap);
/// texture_nearest: a texel's colour exactly (tolerance 0). IllConditioned within rounding of a
/// texel's edge, and exactly on one where the texels either side differ (u = 1 under repeat:
/// floor(u W) reads column 0, a right reading of "the right edge" column W - 1).
Expected<Color> expected_texture_nearest(const Image& image, const Vec2& uv, WrapMode wrap);
Expected<Color> expected_texture_bilinear(const Image& image, const Vec2& uv, WrapMode wrap);
/// normal_from_map; nullopt where the sum is exactly zero (the function throws).
std::optional<Expected<Vec3>> expected_normal_from_map(const TangentFrame& frame,
                                                       const Color& texel);
Expected<Vec2> expected_height_slopes(const Image& height_map, const Vec2& uv, WrapMode wrap,
                                      double scale);
/// bump_normal; nullopt where the cross product is exactly zero (the function throws).
std::optional<Expected<Vec3>> expected_bump_normal(const SurfaceDerivatives& derivatives,
                                                   const Vec3& normal, const Vec2& slopes);

}  // namespace raystep::grade
