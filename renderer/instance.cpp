#include "renderer/instance.h"

#include <algorithm>
#include <cmath>

#include <glm/matrix.hpp>

#include "renderer/render_plan.h"

namespace raystep {

namespace {

double largest_residual(const Transform& transform) {
    const Mat4 product = transform.inverse * transform.matrix;
    double largest = 0.0;
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            const double expected = row == column ? 1.0 : 0.0;
            largest = std::max(largest, std::abs(product[column][row] - expected));
        }
    }
    return largest;
}

// Ray-box tests round, the transform rounds, and M^-1 is not exactly M's inverse; a box that
// holds the geometry only in exact arithmetic could drop a hit the object-frame test reports on
// its very edge, and then the instance BVH would not find exactly brute force's hits. So the box
// grows by a relative 2^-40 of its largest coordinate (thousands of ulps, far more than the
// roundings of one matrix product) plus eight residuals, for transforms whose M^-1 M is far from
// I. renderer/tests/instance_test.cpp holds the BVH to brute force on scaled, rotated and tiny
// objects.
constexpr double kBoundsMargin = 0x1p-40;

Aabb widened(const Aabb& box, double residual) {
    const double magnitude =
        std::max({std::abs(box.min.x), std::abs(box.min.y), std::abs(box.min.z),
                  std::abs(box.max.x), std::abs(box.max.y), std::abs(box.max.z)});
    const Vec3 pad((kBoundsMargin + 8.0 * residual) * magnitude);
    return {box.min - pad, box.max + pad};
}

// The scene's number of a hit on the instance's geometry.
std::size_t scene_id(const Instance& instance, const InstanceGeometry& geometry,
                     const PrimitiveHit& hit) {
    if (hit.kind == PrimitiveKind::sphere) return geometry.sphere_ids[hit.index];
    if (geometry.triangle_ids.empty()) return instance.first_triangle + hit.index;
    return geometry.triangle_ids[hit.index];
}

Ray in_object_frame(const Instance& instance, const Ray& ray) {
    return instance.transform ? ray_to_object(*instance.transform, ray) : ray;
}

}  // namespace

void finish_geometry(InstanceGeometry& geometry) {
    geometry.bounds = Aabb{};
    for (const Sphere& sphere : geometry.primitives.spheres)
        geometry.bounds.add(bounds_of(sphere));
    for (const Triangle& triangle : geometry.primitives.triangles)
        geometry.bounds.add(bounds_of(triangle));
    const std::size_t count =
        geometry.primitives.spheres.size() + geometry.primitives.triangles.size();
    if (count >= kBvhFromPrimitives) geometry.bvh.emplace(geometry.primitives, BvhSplit::sah);
}

void place_instance(Instance& instance, const InstanceGeometry& geometry) {
    if (geometry.bounds.empty()) {
        // A mesh of no faces: nothing to hit, and its infinite corners would make NaN through M.
        instance.inverse_residual = 0.0;
        instance.world_bounds = Aabb{};
        return;
    }
    if (!instance.transform) {
        instance.inverse_residual = 0.0;
        instance.world_bounds = widened(geometry.bounds, 0.0);
        return;
    }
    instance.inverse_residual = largest_residual(*instance.transform);
    instance.mirrors = glm::determinant(glm::dmat3(instance.transform->matrix)) < 0.0;
    Aabb world;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p((corner & 1) ? geometry.bounds.max.x : geometry.bounds.min.x,
                     (corner & 2) ? geometry.bounds.max.y : geometry.bounds.min.y,
                     (corner & 4) ? geometry.bounds.max.z : geometry.bounds.min.z);
        world.add(Vec3(instance.transform->matrix * Vec4(p, 1.0)));
    }
    instance.world_bounds = widened(world, instance.inverse_residual);
}

std::optional<PrimitiveHit> instance_closest_hit(const Instance& instance,
                                                 const InstanceGeometry& geometry, const Ray& ray,
                                                 TraversalStats* stats) {
    const Ray local = in_object_frame(instance, ray);
    std::optional<PrimitiveHit> hit;
    if (geometry.bvh) {
        hit = geometry.bvh->closest_hit(local, stats);
    } else {
        hit = closest_hit(local, geometry.primitives);
        if (stats) {
            stats->primitive_tests +=
                geometry.primitives.spheres.size() + geometry.primitives.triangles.size();
        }
    }
    if (!hit) return std::nullopt;
    hit->index = scene_id(instance, geometry, *hit);
    if (instance.transform) {
        hit->hit.normal = normal_to_world(*instance.transform, hit->hit.normal);
        // A triangle's normal follows its vertices' winding, which a mirror turns over; a
        // sphere's points outward either way.
        if (instance.mirrors && hit->kind == PrimitiveKind::triangle) {
            hit->hit.normal = -hit->hit.normal;
        }
    }
    return hit;
}

bool instance_occluded(const Instance& instance, const InstanceGeometry& geometry, const Ray& ray) {
    const Ray local = in_object_frame(instance, ray);
    if (geometry.bvh) return geometry.bvh->occluded(local, nullptr);
    return closest_hit(local, geometry.primitives).has_value();
}

}  // namespace raystep
