#include "grading/11_surface_detail/surface_detail_oracle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "grader/oracle/wide_vec.h"

namespace raystep::grade {

namespace {

using WideVec2 = glm::vec<2, Wide>;

WideVec2 widen_uv(const Vec2& v) {
    return {v.x, v.y};
}

Vec2 narrow_uv(const WideVec2& v) {
    return {static_cast<double>(v.x), static_cast<double>(v.y)};
}

// The largest magnitude of the components.
Wide magnitude(const Vec2& v) {
    return std::max(std::abs(static_cast<Wide>(v.x)), std::abs(static_cast<Wide>(v.y)));
}

Wide magnitude(const Vec3& v) {
    return std::max({std::abs(static_cast<Wide>(v.x)), std::abs(static_cast<Wide>(v.y)),
                     std::abs(static_cast<Wide>(v.z))});
}

Wide magnitude(const WideVec& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// A unit vector's tolerance after normalizing a sum whose components are off by up to `error`:
// the direction turns by error / length per component (twice, for margin), plus the rounding of
// the normalization itself.
double unit_tolerance(Wide error, Wide length) {
    return static_cast<double>(4 * error / length + 8 * kWideUnitRoundoff);
}

// A length that is not a million times its rounding error: a right formula in double may give a
// direction off by more than a millionth, or none, and throw.
void require_clear_length(Wide length, Wide error, const char* what) {
    if (length < 1e6L * error) throw IllConditioned(std::string(what) + " within rounding of 0");
}

// The largest channel magnitude of the image.
Wide brightest(const Image& image) {
    Wide largest = 0;
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i)
            largest = std::max(largest, magnitude(image.at(i, j)));
    }
    return largest;
}

WideVec bilinear(const Image& image, Wide u, Wide v, WrapMode wrap) {
    const Wide x = u * image.width() - 0.5L;
    const Wide y = (1 - v) * image.height() - 0.5L;
    const Wide x0 = std::floor(x);
    const Wide y0 = std::floor(y);
    const Wide fx = x - x0;
    const Wide fy = y - y0;
    const int i0 = static_cast<int>(x0);
    const int j0 = static_cast<int>(y0);
    const auto texel = [&](int i, int j) {
        return widen(image.at(expected_wrap_texel(i, image.width(), wrap),
                              expected_wrap_texel(j, image.height(), wrap)));
    };
    return (1 - fx) * (1 - fy) * texel(i0, j0) + fx * (1 - fy) * texel(i0 + 1, j0) +
           (1 - fx) * fy * texel(i0, j0 + 1) + fx * fy * texel(i0 + 1, j0 + 1);
}

// How far a right bilinear lookup in double may land from the exact one: (u, v) in texel units
// is off by a few roundings of |u| W and |v| H, which moves the weights by as much; each weight
// multiplies a difference of texels of at most twice the brightest channel.
Wide bilinear_error(const Image& image, const Vec2& uv) {
    const Wide texels = (std::abs(static_cast<Wide>(uv.x)) + 2) * image.width() +
                        (std::abs(static_cast<Wide>(uv.y)) + 2) * image.height() + 2;
    const Wide light = brightest(image);
    return 8 * kWideUnitRoundoff * texels * 2 * light + 8 * kWideUnitRoundoff * light;
}

}  // namespace

std::optional<Expected<Vec3>> expected_interpolate_normal(const Vec3& n0, const Vec3& n1,
                                                          const Vec3& n2, double beta,
                                                          double gamma) {
    const Wide b = beta;
    const Wide g = gamma;
    const WideVec sum = (1 - b - g) * widen(n0) + b * widen(n1) + g * widen(n2);
    const Wide length = glm::length(sum);
    if (length == 0) return std::nullopt;
    // Each component of the double sum: the weights and products round, in any order.
    const Wide error = 16 * kWideUnitRoundoff * (1 + std::abs(b) + std::abs(g)) *
                       (magnitude(n0) + magnitude(n1) + magnitude(n2));
    require_clear_length(length, error, "the interpolated normal");
    return Expected<Vec3>{narrow(sum / length), unit_tolerance(error, length)};
}

Expected<Vec2> expected_interpolate_uv(const Vec2& uv0, const Vec2& uv1, const Vec2& uv2,
                                       double beta, double gamma) {
    const Wide b = beta;
    const Wide g = gamma;
    const WideVec2 uv = (1 - b - g) * widen_uv(uv0) + b * widen_uv(uv1) + g * widen_uv(uv2);
    const Wide error = 16 * kWideUnitRoundoff * (1 + std::abs(b) + std::abs(g)) *
                       (magnitude(uv0) + magnitude(uv1) + magnitude(uv2));
    return {narrow_uv(uv), static_cast<double>(2 * error)};
}

Expected<Vec2> expected_sphere_uv(const Vec3& normal) {
    const WideVec n = widen(normal);
    const Wide across = std::sqrt(n.x * n.x + n.z * n.z);
    if (across == 0) throw IllConditioned("sphere_uv at a pole: u is any");
    if (n.x == 0 && n.z < 0) throw IllConditioned("sphere_uv on the seam: u is 0 or 1");
    const Wide theta = std::atan2(across, n.y);
    const Wide phi = kWidePi + std::atan2(n.x, n.z);
    // Each atan2 in double is within a few ulps of pi; divided by pi or 2 pi, a few ulps of 1.
    return {narrow_uv(WideVec2{phi / (2 * kWidePi), 1 - theta / kWidePi}),
            static_cast<double>(16 * kWideUnitRoundoff)};
}

Expected<std::optional<SurfaceDerivatives>> expected_surface_derivatives(
    const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec2& uv0, const Vec2& uv1,
    const Vec2& uv2) {
    const WideVec e1 = widen(p1) - widen(p0);
    const WideVec e2 = widen(p2) - widen(p0);
    const WideVec2 d1 = widen_uv(uv1) - widen_uv(uv0);
    const WideVec2 d2 = widen_uv(uv2) - widen_uv(uv0);
    const Wide det = d1.x * d2.y - d2.x * d1.y;
    if (det == 0) return {std::nullopt, 0.0};
    const WideVec dpdu = (d2.y * e1 - d1.y * e2) / det;
    const WideVec dpdv = (d1.x * e2 - d2.x * e1) / det;
    // In double: the edges are off by a rounding of the points, the uv edges by one of the uvs;
    // the numerators and the determinant add their products' roundings. The quotient's error is
    // the numerator's over |det| plus the result times the determinant's relative error.
    const Wide points = std::max({magnitude(p0), magnitude(p1), magnitude(p2)});
    const Wide uvs = std::max({magnitude(uv0), magnitude(uv1), magnitude(uv2)});
    const Wide edges = std::max(magnitude(e1), magnitude(e2));
    const Wide uv_edges =
        std::max({std::abs(d1.x), std::abs(d1.y), std::abs(d2.x), std::abs(d2.y)});
    const Wide numerator_error =
        16 * kWideUnitRoundoff * (uv_edges * (2 * points + edges) + edges * (2 * uvs + uv_edges));
    const Wide det_error = 16 * kWideUnitRoundoff * uv_edges * (2 * uvs + uv_edges);
    if (std::abs(det) < 1e6L * det_error)
        throw IllConditioned("surface_derivatives: the determinant within rounding of 0");
    const Wide result = std::max(magnitude(dpdu), magnitude(dpdv));
    const Wide error = (numerator_error + result * det_error) / std::abs(det);
    return {SurfaceDerivatives{narrow(dpdu), narrow(dpdv)}, static_cast<double>(2 * error)};
}

Expected<std::optional<TangentFrame>> expected_tangent_frame(const SurfaceDerivatives& derivatives,
                                                             const Vec3& normal) {
    const WideVec n = widen(normal);
    const WideVec dpdu = widen(derivatives.dpdu);
    const WideVec across = dpdu - glm::dot(n, dpdu) * n;
    const Wide length = glm::length(across);
    if (length == 0) return {std::nullopt, 0.0};
    // The Gram-Schmidt step in double: the dot product and the subtraction round at dp/du's
    // size, and a unit normal's own rounding leaves as much along it.
    const Wide error = 16 * kWideUnitRoundoff * magnitude(dpdu);
    require_clear_length(length, error, "dp/du's part across the normal");
    const WideVec tangent = across / length;
    WideVec bitangent = glm::cross(n, tangent);
    const Wide side = glm::dot(bitangent, widen(derivatives.dpdv));
    // The side is decided by the sign of a dot product: a millionth of dp/dv's size is far above
    // its rounding.
    if (std::abs(side) <= 1e-6L * magnitude(derivatives.dpdv))
        throw IllConditioned("tangent_frame: dp/dv within rounding of the tangent's line");
    if (side < 0) bitangent = -bitangent;
    const double tolerance =
        unit_tolerance(error, length) + static_cast<double>(8 * kWideUnitRoundoff);
    return {TangentFrame{narrow(tangent), narrow(bitangent), normal}, tolerance};
}

int expected_wrap_texel(int i, int size, WrapMode wrap) {
    const long long k = i;
    const long long n = size;
    switch (wrap) {
        case WrapMode::repeat:
            return static_cast<int>(((k % n) + n) % n);
        case WrapMode::clamp:
            return static_cast<int>(std::clamp(k, 0LL, n - 1));
        case WrapMode::mirror: {
            const long long m = ((k % (2 * n)) + 2 * n) % (2 * n);
            return static_cast<int>(m < n ? m : 2 * n - 1 - m);
        }
    }
    throw std::invalid_argument("unknown wrap mode");
}

Expected<Color> expected_texture_nearest(const Image& image, const Vec2& uv, WrapMode wrap) {
    const Wide x = static_cast<Wide>(uv.x) * image.width();
    const Wide y = (1 - static_cast<Wide>(uv.y)) * image.height();
    // A right product in double floors to the same texel unless it is within rounding of a
    // texel's edge (a billionth of a texel is far above a product's rounding at |u| W up to 10^7).
    // Exactly on an edge, floor takes the texel after it, and a reading of the edge as the end of
    // the texel before it (v = 0 as the bottom row) takes that one: the two must agree.
    for (const Wide t : {x, y}) {
        const Wide edge = std::round(t);
        if (t != edge && std::abs(t - edge) < 1e-9L * (1 + std::abs(t)))
            throw IllConditioned("texture_nearest within rounding of a texel's edge");
    }
    const auto texel = [&](Wide column, Wide row) {
        return image.at(expected_wrap_texel(static_cast<int>(column), image.width(), wrap),
                        expected_wrap_texel(static_cast<int>(row), image.height(), wrap));
    };
    const Color colour = texel(std::floor(x), std::floor(y));
    const Wide before_x = std::floor(x) == x ? x - 1 : std::floor(x);
    const Wide before_y = std::floor(y) == y ? y - 1 : std::floor(y);
    if (texel(before_x, before_y) != colour)
        throw IllConditioned("texture_nearest on a texel's edge between two colours");
    return {colour, 0.0};
}

Expected<Color> expected_texture_bilinear(const Image& image, const Vec2& uv, WrapMode wrap) {
    return {narrow(bilinear(image, uv.x, uv.y, wrap)),
            static_cast<double>(2 * bilinear_error(image, uv))};
}

std::optional<Expected<Vec3>> expected_normal_from_map(const TangentFrame& frame,
                                                       const Color& texel) {
    const WideVec local = Wide(2) * widen(texel) - WideVec(1);
    const WideVec sum = local.x * widen(frame.tangent) + local.y * widen(frame.bitangent) +
                        local.z * widen(frame.normal);
    const Wide length = glm::length(sum);
    if (length == 0) return std::nullopt;
    const Wide frame_size =
        std::max({magnitude(frame.tangent), magnitude(frame.bitangent), magnitude(frame.normal)});
    const Wide error = 16 * kWideUnitRoundoff *
                       (std::abs(local.x) + std::abs(local.y) + std::abs(local.z) + 3) * frame_size;
    require_clear_length(length, error, "the mapped normal");
    return Expected<Vec3>{narrow(sum / length), unit_tolerance(error, length)};
}

Expected<Vec2> expected_height_slopes(const Image& height_map, const Vec2& uv, WrapMode wrap,
                                      double scale) {
    const Wide u = uv.x;
    const Wide v = uv.y;
    const Wide w = height_map.width();
    const Wide h = height_map.height();
    const auto height = [&](Wide at_u, Wide at_v) {
        return static_cast<Wide>(scale) * bilinear(height_map, at_u, at_v, wrap).x;
    };
    const WideVec2 slopes{(height(u + 1 / w, v) - height(u - 1 / w, v)) * w / 2,
                          (height(u, v + 1 / h) - height(u, v - 1 / h)) * h / 2};
    // Each height is off by a lookup's error times the scale; their difference, over a step of
    // two texels, by W (or H) times that, and the quotient rounds once more.
    const Vec2 reach = {std::abs(uv.x) + 1, std::abs(uv.y) + 1};
    const Wide lookup = std::abs(static_cast<Wide>(scale)) * bilinear_error(height_map, reach);
    const Wide error = 2 * lookup * std::max(w, h) +
                       8 * kWideUnitRoundoff * std::max(std::abs(slopes.x), std::abs(slopes.y));
    return {narrow_uv(slopes), static_cast<double>(2 * error)};
}

std::optional<Expected<Vec3>> expected_bump_normal(const SurfaceDerivatives& derivatives,
                                                   const Vec3& normal, const Vec2& slopes) {
    const WideVec n = widen(normal);
    const WideVec a = widen(derivatives.dpdu) + static_cast<Wide>(slopes.x) * n;
    const WideVec b = widen(derivatives.dpdv) + static_cast<Wide>(slopes.y) * n;
    WideVec bumped = glm::cross(a, b);
    const Wide length = glm::length(bumped);
    if (length == 0) return std::nullopt;
    // The bumped derivatives round at their inputs' sizes, and the cross product's components
    // are differences of products of them. Its expanded form, dp/du x dp/dv + h_v dp/du x n +
    // h_u n x dp/dv (Blinn's), rounds at the products of those sizes instead of the sums', which
    // are larger where dp/dv + h_v n nearly cancels: the bound takes the sizes.
    const Wide a_size = magnitude(derivatives.dpdu) + std::abs(slopes.x) * magnitude(normal);
    const Wide b_size = magnitude(derivatives.dpdv) + std::abs(slopes.y) * magnitude(normal);
    const Wide error = 16 * kWideUnitRoundoff * a_size * b_size;
    require_clear_length(length, error, "the bumped normal");
    const Wide side = glm::dot(bumped, n);
    if (std::abs(side) <= 1e-6L * length)
        throw IllConditioned("bump_normal: the bumped normal within rounding of the surface");
    if (side < 0) bumped = -bumped;
    return Expected<Vec3>{narrow(bumped / length), unit_tolerance(error, length)};
}

}  // namespace raystep::grade
