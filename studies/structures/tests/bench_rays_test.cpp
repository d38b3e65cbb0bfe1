#include "studies/structures/bench_rays.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "base/testing/catch.h"

using namespace raystep;

namespace {

// The bunny00.off box, rounded: the shape the bunny workloads frame.
const Aabb kBunnyBox{{-0.095, 0.033, -0.062}, {0.061, 0.187, 0.059}};

// True when the ray meets the box: a plain slab test (stage 4's is what the bench measures, not
// what checks it).
bool meets(const Ray& ray, const Aabb& box) {
    double enter = 0.0;
    double exit = INFINITY;
    for (int axis = 0; axis < 3; ++axis) {
        const double t0 = (box.min[axis] - ray.origin[axis]) / ray.direction[axis];
        const double t1 = (box.max[axis] - ray.origin[axis]) / ray.direction[axis];
        enter = std::max(enter, std::min(t0, t1));
        exit = std::min(exit, std::max(t0, t1));
    }
    return enter <= exit;
}

}  // namespace

TEST_CASE("incoherent_rays: the same seed makes the same rays, another seed other rays",
          "[bench]") {
    const std::vector<Ray> a = incoherent_rays(kBunnyBox, 1000, 167);
    const std::vector<Ray> b = incoherent_rays(kBunnyBox, 1000, 167);
    const std::vector<Ray> c = incoherent_rays(kBunnyBox, 1000, 168);
    REQUIRE(a.size() == 1000);
    for (std::size_t k = 0; k < a.size(); ++k) {
        CAPTURE(k);
        REQUIRE(a[k].origin == b[k].origin);
        REQUIRE(a[k].direction == b[k].direction);
    }
    CHECK(a[0].origin != c[0].origin);
}

TEST_CASE("incoherent_rays: from the sphere of twice the diagonal, each through the box",
          "[bench]") {
    const double radius = 2.0 * glm::length(kBunnyBox.extent());
    const std::vector<Ray> rays = incoherent_rays(kBunnyBox, 2000, 7);
    double mean_z = 0.0;
    for (std::size_t k = 0; k < rays.size(); ++k) {
        CAPTURE(k);
        REQUIRE(glm::length(rays[k].origin - kBunnyBox.center()) == Approx(radius).epsilon(1e-12));
        REQUIRE(glm::length(rays[k].direction) == Approx(1.0).epsilon(1e-12));
        REQUIRE(meets(rays[k], kBunnyBox));
        mean_z += (rays[k].origin.z - kBunnyBox.center().z) / radius;
    }
    // Uniform on the sphere: the mean of z over 2000 points is within a few 1/sqrt(3 n) of 0
    CHECK(std::abs(mean_z / rays.size()) < 0.05);
}

TEST_CASE("primary_rays: row by row from one eye, and the box fills the view", "[bench]") {
    const int width = 64;
    const int height = 48;
    const std::vector<Ray> rays = primary_rays(kBunnyBox, width, height);
    REQUIRE(rays.size() == static_cast<std::size_t>(width * height));

    std::size_t hits = 0;
    for (std::size_t k = 0; k < rays.size(); ++k) {
        CAPTURE(k);
        REQUIRE(rays[k].origin == rays[0].origin);
        REQUIRE(glm::length(rays[k].direction) == Approx(1.0).epsilon(1e-12));
        hits += meets(rays[k], kBunnyBox) ? 1 : 0;
    }
    // The eye is outside the box, on the side of kBenchViewDirection
    CHECK(glm::dot(rays[0].origin - kBunnyBox.center(), kBenchViewDirection) > 0.0);
    // The four rays around the image centre hit the box, the corners' miss it, and the box
    // covers a good part of the image
    for (const int i : {width / 2 - 1, width / 2}) {
        for (const int j : {height / 2 - 1, height / 2}) {
            CAPTURE(i, j);
            CHECK(meets(rays[static_cast<std::size_t>(j * width + i)], kBunnyBox));
        }
    }
    CHECK_FALSE(meets(rays.front(), kBunnyBox));
    CHECK_FALSE(meets(rays.back(), kBunnyBox));
    CHECK(hits > rays.size() / 5);
    // The first ray, top left, looks further up than the last, bottom right
    CHECK(rays.front().direction.y > rays.back().direction.y);
}

TEST_CASE("bench_bounds: the box of spheres and triangles together", "[bench]") {
    PrimitiveList list;
    list.spheres.push_back({{0, 0, 0}, 1});
    list.triangles.push_back({{2, 0, 0}, {3, 1, 0}, {2, 0, 5}});
    const Aabb box = bench_bounds(list);
    CHECK(box.min.x <= -1.0);
    CHECK(box.max.x == 3.0);
    CHECK(box.max.z == 5.0);
    CHECK(bench_bounds(PrimitiveList{}).empty());
}
