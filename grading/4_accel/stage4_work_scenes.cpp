#include "grading/4_accel/stage4_work_scenes.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "base/math/portable_random.h"

namespace raystep::grade {

namespace {

constexpr std::uint64_t kStrewnSeed = 0x3017C;
constexpr std::uint64_t kSpeedSoupSeed = 0x5BEED;
constexpr std::uint64_t kSpeedSeed = 3;

}  // namespace

WorkScene strewn_scene() {
    constexpr int kTriangles = 1500;
    constexpr int kSpheres = 150;
    constexpr int kRays = 400;
    WorkScene scene;
    scene.name = "the strewn scene (" + std::to_string(kTriangles) + " triangles and " +
                 std::to_string(kSpheres) + " spheres from seed " + std::to_string(kStrewnSeed) +
                 ")";
    PortableRandom random(kStrewnSeed);
    for (int k = 0; k < kTriangles; ++k) {
        const Vec3 c = random.point(1.0);
        scene.primitives.triangles.push_back({c, c + random.point(0.1), c + random.point(0.1)});
    }
    for (int k = 0; k < kSpheres; ++k)
        scene.primitives.spheres.push_back({random.point(1.0), random.uniform(0.01, 0.08)});
    for (int k = 0; k < kRays; ++k) {
        const Vec3 origin = 3.0 * random.unit_vector();
        Ray ray{origin, random.point(0.8) - origin};
        if (k % 4 == 1) ray.t_min = random.uniform(0.3, 0.8);
        if (k % 4 == 2) ray.t_max = random.uniform(0.5, 1.2);
        scene.rays.push_back(ray);
    }
    return scene;
}

PrimitiveList soup_primitives(PortableRandom& random) {
    PrimitiveList primitives;
    for (int k = 0; k < 300; ++k) {
        const Vec3 c = random.point(1.0);
        primitives.triangles.push_back({c, c + random.point(0.2), c + random.point(0.2)});
    }
    for (int k = 0; k < 60; ++k)
        primitives.spheres.push_back({random.point(1.0), random.uniform(0.01, 0.15)});
    for (int k = 0; k < 3; ++k)
        primitives.planes.push_back({random.point(1.0), random.unit_vector()});
    return primitives;
}

WorkScene speed_scene(int rays) {
    constexpr int kSmallTriangles = 3000;
    PortableRandom soup(kSpeedSoupSeed);
    WorkScene scene;
    scene.primitives = soup_primitives(soup);
    PortableRandom random(kSpeedSeed);
    for (int k = 0; k < kSmallTriangles; ++k) {
        const Vec3 c = random.point(1.0);
        scene.primitives.triangles.push_back({c, c + random.point(0.05), c + random.point(0.05)});
    }
    scene.name = "the speed scene (" + std::to_string(scene.primitives.triangles.size()) +
                 " triangles and " + std::to_string(scene.primitives.spheres.size()) + " spheres)";
    for (int k = 0; k < rays; ++k) {
        const Vec3 origin = 3.0 * random.unit_vector();
        scene.rays.push_back({origin, random.point(0.8) - origin});
    }
    return scene;
}

WorkScene walls_scene(int layers, Side side) {
    constexpr int kSide = 2;
    constexpr int kRays = 1000;
    WorkScene scene;
    scene.name = "the walls scene (" + std::to_string(layers) + (layers == 1 ? " wall" : " walls") +
                 " of " + std::to_string(2 * kSide * kSide) + " triangles, rays from " +
                 (side == Side::above   ? "above"
                  : side == Side::below ? "below"
                                        : "both sides") +
                 ", seed " + std::to_string(kTraversalSeed) + ")";
    const double step = 1.0 / kSide;
    for (int layer = 0; layer < layers; ++layer) {
        const double z = kWallsHeight * (layer + 0.5) / layers;
        for (int i = 0; i < kSide; ++i) {
            for (int j = 0; j < kSide; ++j) {
                const Vec3 a(i * step, j * step, z), b((i + 1) * step, j * step, z);
                const Vec3 c((i + 1) * step, (j + 1) * step, z), d(i * step, (j + 1) * step, z);
                scene.primitives.triangles.push_back({a, b, c});
                scene.primitives.triangles.push_back({a, c, d});
            }
        }
    }
    // Two specks at opposite corners, so that every number of walls fills the same box
    for (const Vec3 corner : {Vec3(0.0), Vec3(1.0, 1.0, kWallsHeight)})
        scene.primitives.triangles.push_back(
            {corner, corner + Vec3(1e-3, 0, 0), corner + Vec3(0, 1e-3, 0)});
    // Each ray enters through the top or the bottom and leaves through the other: from a point
    // 1 beyond one end to a point 1 beyond the other, both within 0.4 of the column's axis, a
    // unit direction, so that it crosses every wall.
    PortableRandom random(kTraversalSeed);
    for (int k = 0; k < kRays; ++k) {
        const bool down = side == Side::above || (side == Side::both && k % 2 == 0);
        const double from_z = down ? kWallsHeight + 1.0 : -1.0;
        const double to_z = down ? -1.0 : kWallsHeight + 1.0;
        const Vec3 origin(0.5 + random.uniform(-0.4, 0.4), 0.5 + random.uniform(-0.4, 0.4), from_z);
        const Vec3 to(0.5 + random.uniform(-0.4, 0.4), 0.5 + random.uniform(-0.4, 0.4), to_z);
        scene.rays.push_back({origin, glm::normalize(to - origin)});
    }
    return scene;
}

std::vector<Ray> shadow_rays(const WorkScene& scene) {
    std::vector<Ray> shadows = scene.rays;
    for (Ray& ray : shadows)
        ray.t_max = 0.25;
    return shadows;
}

}  // namespace raystep::grade
