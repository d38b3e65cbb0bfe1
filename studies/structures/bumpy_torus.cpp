#include "studies/structures/bumpy_torus.h"

#include <cmath>

namespace raystep {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
constexpr double kTorusRadius = 1.0;
constexpr double kTubeRadius = 0.3;

// The point at angle a around the y axis and angle b around the tube. The bumps' frequencies are
// coprime with each other and independent of the tessellation, so the surface is the same at
// every size and only sampled more finely.
Vec3 torus_point(double a, double b) {
    const double bumps = 0.2 * std::sin(7.0 * a) * std::sin(5.0 * b) +
                         0.1 * std::sin(23.0 * a + 3.0 * b) + 0.05 * std::sin(41.0 * b - 11.0 * a);
    const double tube = kTubeRadius * (1.0 + bumps);
    const double from_axis = kTorusRadius + tube * std::cos(b);
    return {from_axis * std::cos(a), tube * std::sin(b), from_axis * std::sin(a)};
}

}  // namespace

std::vector<Triangle> bumpy_torus(int rings, int segments) {
    // The grid of points, wrapping around in both directions
    std::vector<Vec3> points;
    points.reserve(static_cast<std::size_t>(rings) * static_cast<std::size_t>(segments));
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < segments; ++j) {
            points.push_back(torus_point(kTwoPi * i / rings, kTwoPi * j / segments));
        }
    }
    const auto at = [&](int i, int j) -> const Vec3& {
        return points[static_cast<std::size_t>((i % rings) * segments + j % segments)];
    };

    // Two triangles per quad of the grid
    std::vector<Triangle> triangles;
    triangles.reserve(2 * points.size());
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < segments; ++j) {
            triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    }
    return triangles;
}

}  // namespace raystep
