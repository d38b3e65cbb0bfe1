#include "studies/structures/bench_geometry.h"

#include <cmath>

#include "base/math/portable_random.h"
#include "stages/4_accel/aabb.h"

namespace raystep {

std::vector<Triangle> mesh_triangles(const TriangleMesh& mesh) {
    std::vector<Triangle> triangles;
    triangles.reserve(mesh.faces.size());
    for (const auto& face : mesh.faces) {
        triangles.push_back(
            {mesh.positions[face[0]], mesh.positions[face[1]], mesh.positions[face[2]]});
    }
    return triangles;
}

std::vector<Triangle> tiled_copies(const std::vector<Triangle>& triangles, int columns, int rows,
                                   double spacing) {
    Aabb box;
    for (const Triangle& triangle : triangles)
        box.add(bounds_of(triangle));
    const Vec3 step = spacing * box.extent();

    std::vector<Triangle> copies;
    copies.reserve(triangles.size() * static_cast<std::size_t>(columns * rows));
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            const Vec3 shift(column * step.x, 0.0, row * step.z);
            for (const Triangle& t : triangles) {
                copies.push_back({t.p0 + shift, t.p1 + shift, t.p2 + shift});
            }
        }
    }
    return copies;
}

std::vector<Sphere> random_spheres(std::size_t count, std::uint64_t seed) {
    PortableRandom random(seed);
    const double side = std::cbrt(1.0 / static_cast<double>(count));
    std::vector<Sphere> spheres;
    spheres.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3 center(random.unit(), random.unit(), random.unit());
        spheres.push_back({center, side * random.uniform(0.25, 0.75)});
    }
    return spheres;
}

std::vector<Triangle> random_triangles(std::size_t count, std::uint64_t seed) {
    PortableRandom random(seed);
    const double half = 0.5 * std::cbrt(1.0 / static_cast<double>(count));
    const auto near = [&](const Vec3& center) {
        return center + Vec3(random.uniform(-half, half), random.uniform(-half, half),
                             random.uniform(-half, half));
    };
    std::vector<Triangle> triangles;
    triangles.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3 center(random.unit(), random.unit(), random.unit());
        const Vec3 p0 = near(center);
        const Vec3 p1 = near(center);
        const Vec3 p2 = near(center);
        triangles.push_back({p0, p1, p2});
    }
    return triangles;
}

}  // namespace raystep
