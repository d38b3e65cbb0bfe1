#include "studies/structures/bench_rays.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "base/math/portable_random.h"

namespace raystep {

Aabb bench_bounds(const PrimitiveList& primitives) {
    Aabb box;
    for (const Sphere& sphere : primitives.spheres)
        box.add(bounds_of(sphere));
    for (const Triangle& triangle : primitives.triangles)
        box.add(bounds_of(triangle));
    return box;
}

std::vector<Ray> primary_rays(const Aabb& box, int width, int height) {
    constexpr double kPi = 3.14159265358979323846;

    // The camera frame: w points back towards the camera, u to the right, v up
    const Vec3 w = glm::normalize(kBenchViewDirection);
    const Vec3 u = glm::normalize(glm::cross(Vec3(0.0, 1.0, 0.0), w));
    const Vec3 v = glm::cross(w, u);

    // Far enough back that the bounding sphere's silhouette meets the top and bottom edges
    const double half_angle = 0.5 * kBenchFieldOfView * kPi / 180.0;
    const double radius = 0.5 * glm::length(box.extent());
    const Vec3 eye = box.center() + (radius / std::sin(half_angle)) * w;

    // Rays through pixel centres (i + 0.5, j + 0.5), j counted down from the top row
    const double half_height = std::tan(half_angle);
    const double half_width = half_height * width / height;
    std::vector<Ray> rays;
    rays.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    for (int j = 0; j < height; ++j) {
        const double y = half_height * (1.0 - 2.0 * (j + 0.5) / height);
        for (int i = 0; i < width; ++i) {
            const double x = half_width * (2.0 * (i + 0.5) / width - 1.0);
            rays.push_back(Ray{eye, glm::normalize(x * u + y * v - w)});
        }
    }
    return rays;
}

std::vector<Ray> incoherent_rays(const Aabb& box, std::size_t count, std::uint64_t seed) {
    constexpr double kTwoPi = 6.28318530717958647692;
    PortableRandom random(seed);
    const Vec3 center = box.center();
    const double radius = 2.0 * glm::length(box.extent());

    std::vector<Ray> rays;
    rays.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
        // A point uniform on the sphere: z uniform in [-1, 1], the azimuth uniform (Archimedes)
        const double z = random.uniform(-1.0, 1.0);
        const double azimuth = kTwoPi * random.unit();
        const double ring = std::sqrt(1.0 - z * z);
        const Vec3 origin =
            center + radius * Vec3(ring * std::cos(azimuth), ring * std::sin(azimuth), z);

        const Vec3 target(random.uniform(box.min.x, box.max.x),
                          random.uniform(box.min.y, box.max.y),
                          random.uniform(box.min.z, box.max.z));
        rays.push_back(Ray{origin, glm::normalize(target - origin)});
    }
    return rays;
}

}  // namespace raystep
