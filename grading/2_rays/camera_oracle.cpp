#include "grading/2_rays/camera_oracle.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "base/math/unit_roundoff.h"

namespace raystep {

namespace {

// The point of the image plane (at distance 1 from the eye) through pixel (i, j)'s centre, in
// world directions; the half width scaled by `width_factor`.
WideVec image_plane_point(const WideFrame& f, const CameraCase& c, Wide half_angle,
                          Wide width_factor, int i, int j) {
    const Wide half_height = std::tan(half_angle);
    const Wide half_width = half_height * c.width / c.height * width_factor;
    const Wide alpha = 2 * (i + 0.5L) / c.width - 1;
    const Wide beta = 1 - 2 * (j + 0.5L) / c.height;
    return alpha * half_width * f.u + beta * half_height * f.v - f.w;
}

}  // namespace

WideFrame wide_frame(const CameraCase& c) {
    const WideVec a = widen(c.lookfrom) - widen(c.lookat);
    const WideVec w = a / glm::length(a);
    const WideVec up_cross_w = glm::cross(widen(c.up), w);
    const Wide sine = glm::length(up_cross_w);
    const WideVec u = up_cross_w / sine;
    return {u, glm::cross(w, u), w, sine / glm::length(widen(c.up))};
}

ExpectedCameraRay expected_perspective(const CameraCase& c, int i, int j) {
    const WideFrame f = wide_frame(c);
    const Wide half_angle = c.fovy * kWidePi / 360;
    const WideVec through = image_plane_point(f, c, half_angle, 1, i, j);
    const WideVec direction = through / glm::length(through);

    // What a right implementation cannot help: its half angle is a few roundings off, which the
    // tangent magnifies near 90 degrees; and the half width, taken by the CSE167 route
    // tan(atan(half_height width / height)) as often as directly, inherits atan's rounding
    // magnified the same way. The directions within those perturbations are all right.
    const Wide phi = std::atan(std::tan(half_angle) * c.width / c.height);
    const Wide width_spread = 4 * kUnitRoundoff * phi / (std::sin(phi) * std::cos(phi));
    const Wide perturbations[4][2] = {{1 - 4 * kUnitRoundoff, 1},
                                      {1 + 4 * kUnitRoundoff, 1},
                                      {1, 1 - width_spread},
                                      {1, 1 + width_spread}};
    Wide spread = 0;
    for (const auto& p : perturbations) {
        const WideVec other = image_plane_point(f, c, half_angle * p[0], p[1], i, j);
        const WideVec moved = other / glm::length(other) - direction;
        spread = std::max({spread, std::abs(moved.x), std::abs(moved.y), std::abs(moved.z)});
    }
    // Each term of the image-plane point rounds at a few ulps of the half extents and of 1, the
    // frame's vectors at a few ulps over the sine between up and the view; normalizing divides
    // by the point's length.
    const Wide half_height = std::tan(half_angle);
    const Wide size =
        (half_height * c.width / c.height + half_height + 1) / (glm::length(through) * f.up_sine);
    return {c.lookfrom, 0.0, narrow(direction),
            static_cast<double>(8 * kUnitRoundoff * size + spread)};
}

ExpectedCameraRay expected_orthographic(const CameraCase& c, int i, int j) {
    const WideFrame f = wide_frame(c);
    const Wide x = c.left + (Wide(c.right) - c.left) * (i + 0.5L) / c.width;
    const Wide y = c.top - (Wide(c.top) - c.bottom) * (j + 0.5L) / c.height;
    const WideVec origin = widen(c.lookfrom) + x * f.u + y * f.v;
    // The window coordinates round at a few ulps of its edges, u and v carry the frame's
    // rounding, and the sum rounds at the eye's ulps.
    const Wide window = std::abs(Wide(c.left)) + std::abs(Wide(c.right)) +
                        std::abs(Wide(c.bottom)) + std::abs(Wide(c.top));
    const Wide eye = std::max(
        {std::abs(Wide(c.lookfrom.x)), std::abs(Wide(c.lookfrom.y)), std::abs(Wide(c.lookfrom.z))});
    return {narrow(origin), static_cast<double>(8 * kUnitRoundoff * (eye + window / f.up_sine)),
            narrow(-f.w), 8 * kUnitRoundoff};
}

}  // namespace raystep
