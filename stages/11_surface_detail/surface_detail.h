#pragma once

#include <optional>

#include "base/image/image.h"
#include "base/image/wrap_mode.h"
#include "base/math/types.h"

namespace raystep {

// Stage 11: surface detail. Handout: docs/stage11.md.
//
// A hit says where a ray meets a surface; what the surface looks like there comes after the hit,
// from values attached to the surface and looked up where the ray landed:
// - a smooth normal, interpolated from the normals at the triangle's vertices;
// - a colour, read from an image at the interpolated texture coordinates (u, v);
// - a perturbed normal, read from a normal map or made from the slopes of a height map, in the
//   surface's tangent frame.
// Shading uses the new normal. The geometry keeps the geometric one: stage 6's shadow-ray offsets
// and every side test stay on it.

// --- Interpolation (interpolation.cpp) -------------------------------------------------------

/// The normal at barycentric coordinates (beta, gamma) of a triangle whose vertices carry the
/// normals n0, n1, n2: normalize((1 - beta - gamma) n0 + beta n1 + gamma n2). The vertex normals
/// need not be unit length (an OBJ file's are not always). Throws std::domain_error where the
/// sum's length is 0, which only vertex normals that oppose each other give.
Vec3 interpolate_normal(const Vec3& n0, const Vec3& n1, const Vec3& n2, double beta, double gamma);

/// The texture coordinates at barycentric coordinates (beta, gamma) of a triangle whose vertices
/// carry uv0, uv1, uv2: (1 - beta - gamma) uv0 + beta uv1 + gamma uv2.
Vec2 interpolate_uv(const Vec2& uv0, const Vec2& uv1, const Vec2& uv2, double beta, double gamma);

/// A sphere's texture coordinates at the unit normal n (y up), by the lecture's spherical angles:
/// the polar angle theta = atan2(sqrt(n.x^2 + n.z^2), n.y) from the north pole, and the azimuth
/// phi = pi + atan2(n.x, n.z) about y; u = phi / (2 pi), v = 1 - theta / pi. So v is 1 at the
/// north pole and 0 at the south, u is 0.5 where n = +z and grows towards +x, and the seam
/// (u = 0 or 1) is on the -z side. theta by atan2 rather than acos(n.y): acos loses half its
/// digits near the poles, where n.y is within rounding of 1.
Vec2 sphere_uv(const Vec3& normal);

// --- The tangent frame (tangent_frame.cpp) ----------------------------------------------------

/// How a surface point p moves as its texture coordinates move: dp/du and dp/dv.
struct SurfaceDerivatives {
    Vec3 dpdu;
    Vec3 dpdv;
};

/// dp/du and dp/dv over a triangle: the edges e1 = p1 - p0 and e2 = p2 - p0 are the uv edges
/// (du1, dv1) = uv1 - uv0 and (du2, dv2) = uv2 - uv0 mapped onto the surface,
///   e1 = du1 dp/du + dv1 dp/dv,   e2 = du2 dp/du + dv2 dp/dv,
/// two equations solved by Cramer's rule with the determinant du1 dv2 - du2 dv1. nullopt where
/// that determinant is 0: the uv triangle has no area, and u and v give no directions.
std::optional<SurfaceDerivatives> surface_derivatives(const Vec3& p0, const Vec3& p1,
                                                      const Vec3& p2, const Vec2& uv0,
                                                      const Vec2& uv1, const Vec2& uv2);

/// An orthonormal frame at a surface point, in which normal maps are written: the tangent follows
/// u, the bitangent v, the normal leaves the surface.
struct TangentFrame {
    Vec3 tangent;
    Vec3 bitangent;
    Vec3 normal;
};

/// The frame at a point of unit normal n: the tangent is dp/du made orthogonal to n by one
/// Gram-Schmidt step, dp/du - (n . dp/du) n, normalized; the bitangent is n x tangent, negated
/// where it points away from dp/dv (a mirrored texture's uvs run the other way round); the normal
/// is n. nullopt where dp/du has no part orthogonal to n (it is zero or parallel to n).
std::optional<TangentFrame> tangent_frame(const SurfaceDerivatives& derivatives,
                                          const Vec3& normal);

// --- Texture lookup (texture.cpp) -------------------------------------------------------------

/// The texel that index i, any integer, reads in a row or column of `size` texels (size >= 1),
/// by the WrapMode (base/image/wrap_mode.h):
/// - repeat: i mod size, in [0, size) for negative i too;
/// - clamp: i limited to [0, size - 1];
/// - mirror: 0, 1, ..., size - 1, then size - 1, ..., 1, 0, and so on both ways, period 2 size.
int wrap_texel(int i, int size, WrapMode wrap);

/// The texel (u, v) falls in. u runs from the image's left edge (0) to its right (1), v from its
/// bottom row (0) to its top (1), and row 0 of an Image is the top: column floor(u W), row
/// floor((1 - v) H), each wrapped. The image has at least one texel and at most a million a
/// side, and |u|, |v| <= 1000, so that every index fits an int.
Color texture_nearest(const Image& image, const Vec2& uv, WrapMode wrap);

/// Bilinear filtering: texel (i, j)'s centre is at u = (i + 0.5) / W, v = 1 - (j + 0.5) / H. In
/// texel units (u, v) is x = u W - 0.5, y = (1 - v) H - 0.5; the four texels around it are
/// (floor x, floor y), one right, one down, and one right and down, each index wrapped, weighted
/// by (1 - fx)(1 - fy), fx (1 - fy), (1 - fx) fy and fx fy, with fx = x - floor x and
/// fy = y - floor y. The same image and range as texture_nearest.
Color texture_bilinear(const Image& image, const Vec2& uv, WrapMode wrap);

// --- Perturbed normals (perturbed_normals.cpp) -----------------------------------------------

/// The normal a tangent-space normal map's texel holds: its colour (r, g, b) in [0, 1] read as
/// the components (2r - 1, 2g - 1, 2b - 1) along the frame's tangent, bitangent and normal, then
/// normalized. The texel (0.5, 0.5, 1) holds the unperturbed normal. Throws std::domain_error
/// where the sum's length is 0 (the texel (0.5, 0.5, 0.5)).
Vec3 normal_from_map(const TangentFrame& frame, const Color& texel);

/// The slopes (dh/du, dh/dv) of a height map at (u, v), by central differences one texel either
/// side:
/// dh/du = (h(u + 1/W, v) - h(u - 1/W, v)) / (2 / W), dh/dv likewise with 1/H, where h is
/// `scale` times the red channel of texture_bilinear (a grey image's value: read_image spreads
/// grey to RGB). `scale` is the bump's height at the map's value 1, in the scene's units.
Vec2 height_slopes(const Image& height_map, const Vec2& uv, WrapMode wrap, double scale);

/// The bumped normal (Blinn, 1978). The surface moved by h along its normal n has, to first
/// order, the derivatives dp/du + (dh/du) n and dp/dv + (dh/dv) n; the bumped normal is their
/// cross product, normalized and turned to n's side. (Blinn's terms h dn/du and h dn/dv are left
/// out: they are small where h is small against the surface's curvature.) n is unit. Throws
/// std::domain_error where the cross product's length is 0.
Vec3 bump_normal(const SurfaceDerivatives& derivatives, const Vec3& normal, const Vec2& slopes);

}  // namespace raystep
