#include "renderer/surface_point.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "base/math/unit_roundoff.h"
#include "stages/11_surface_detail/surface_detail.h"

namespace raystep {

namespace {

// Higham's gamma(n) = n u / (1 - n u): n roundings of relative size u = 2^-53 at most multiply a
// value by (1 + theta) with |theta| <= gamma(n).
constexpr double rounding_gamma(int n) {
    return n * kUnitRoundoff / (1.0 - n * kUnitRoundoff);
}

// A point and the bound on how far rounding may have put it off the surface, per coordinate:
// the surface passes within sum |n_i| error_i of it along the unit normal n.
struct PlacedPoint {
    Vec3 position;
    Vec3 error;
};

// p = alpha p0 + beta p1 + gamma p2: three products and two sums, gamma(7) of the terms' sizes
// with room to spare (pbrt-v4's bound). alpha = 1 - beta - gamma is rounded too, so the weights
// sum to 1 within 2 u; that shifts the point by up to 2 u |p0|, which the last term covers.
PlacedPoint on_triangle(const Triangle& triangle, double beta, double gamma) {
    const double alpha = 1.0 - beta - gamma;
    const Vec3 position = alpha * triangle.p0 + beta * triangle.p1 + gamma * triangle.p2;
    const Vec3 error =
        rounding_gamma(7) * (glm::abs(alpha * triangle.p0) + glm::abs(beta * triangle.p1) +
                             glm::abs(gamma * triangle.p2)) +
        rounding_gamma(2) * glm::abs(triangle.p0);
    return {position, error};
}

// The point pushed back onto the sphere along its radius: w = (p - c) r / |p - c| has length
// r (1 +- gamma(5)) (a subtraction, a length, a division, a product), and c + w rounds once
// more. Only the radial error moves the point off the sphere; it is gamma(5) |w_i| per
// coordinate, plus the last sum's u (|c_i| + |w_i|).
PlacedPoint on_sphere(const Sphere& sphere, const Vec3& near_point) {
    const Vec3 radial = near_point - sphere.center;
    const double distance = glm::length(radial);
    const Vec3 w =
        distance > 0.0 ? radial * (sphere.radius / distance) : Vec3(0.0, 0.0, sphere.radius);
    return {sphere.center + w, rounding_gamma(6) * (glm::abs(w) + glm::abs(sphere.center))};
}

// The point projected onto the plane: p' = p - s n with s = (p - q) . n / (n . n). The distance
// of p' to the plane is off by at most gamma(7) |s| |n| (from s) plus gamma(4) of the sizes of
// p - q along n plus the rounding of p - s n; each is below sum |n_i| / |n| times the matching
// term of the bound.
PlacedPoint on_plane(const Plane& plane, const Vec3& near_point) {
    const double s =
        glm::dot(near_point - plane.point, plane.normal) / glm::dot(plane.normal, plane.normal);
    const Vec3 position = near_point - s * plane.normal;
    const Vec3 error = rounding_gamma(8) * (glm::abs(near_point) + glm::abs(plane.point) +
                                            glm::abs(position) + glm::abs(s * plane.normal));
    return {position, error};
}

// An object-frame point taken to the world by M. The product adds gamma(4) of its terms' sizes
// and carries the object-frame error through |M|. One more term: the intersection tests see the
// world through M^-1, and M^-1 M differs from I by the residual, so the point as those tests see
// it is off by up to residual (|q|_1 + 1) in the object frame.
PlacedPoint to_world(const Instance& instance, const PlacedPoint& local) {
    const Mat4& m = instance.transform->matrix;
    Vec3 size(0.0);
    Vec3 carried(0.0);
    const Vec3 q = local.position;
    const double mismatch =
        instance.inverse_residual * (std::abs(q.x) + std::abs(q.y) + std::abs(q.z) + 1.0);
    for (int row = 0; row < 3; ++row) {
        size[row] = std::abs(m[3][row]);
        for (int column = 0; column < 3; ++column) {
            size[row] += std::abs(m[column][row] * q[column]);
            carried[row] += std::abs(m[column][row]) * (local.error[column] + 2.0 * mismatch);
        }
    }
    return {point_to_world(*instance.transform, q),
            rounding_gamma(4) * size + (1.0 + rounding_gamma(4)) * carried};
}

// The point on the primitive in its own frame: for an instance's, the object-frame ray's.
PlacedPoint place_in_object_frame(const RenderScene& render_scene, const Ray& object_ray,
                                  const PrimitiveHit& hit) {
    switch (hit.kind) {
        case PrimitiveKind::triangle:
            return on_triangle(triangle_shape(render_scene, hit.index), hit.hit.beta,
                               hit.hit.gamma);
        case PrimitiveKind::plane:
            return on_plane(render_scene.primitives.planes[hit.index], object_ray.at(hit.hit.t));
        case PrimitiveKind::sphere:
            return on_sphere(render_scene.scene->spheres[hit.index].shape,
                             object_ray.at(hit.hit.t));
    }
    throw std::logic_error("surface_point: unknown primitive kind");
}

PlacedPoint place(const RenderScene& render_scene, const Ray& ray, const PrimitiveHit& hit) {
    const Instance* instance = instance_of(render_scene, hit.kind, hit.index);
    if (!instance || !instance->transform) return place_in_object_frame(render_scene, ray, hit);
    const Ray object_ray = ray_to_object(*instance->transform, ray);
    return to_world(*instance, place_in_object_frame(render_scene, object_ray, hit));
}

// A smooth triangle's normal at the hit (a `trinormal` triangle's, or a mesh's with vertex
// normals): stage 11's interpolation of its vertex normals, each made unit first, as CSE167's
// ray tracer does, so that a long normal written in the file does not outweigh the others; taken
// to the world by M^-T when a transform places it. nullopt where the vertex normals cancel.
std::optional<Vec3> interpolated_normal(const RenderScene& render_scene, std::size_t index,
                                        std::int32_t vertex_normals, const Hit& hit) {
    const VertexNormals& n =
        render_scene.scene->vertex_normals[static_cast<std::size_t>(vertex_normals)];
    Vec3 smooth;
    try {
        smooth = interpolate_normal(glm::normalize(n.n0), glm::normalize(n.n1),
                                    glm::normalize(n.n2), hit.beta, hit.gamma);
    } catch (const std::domain_error&) {
        return std::nullopt;
    }
    const Instance* instance = instance_of(render_scene, PrimitiveKind::triangle, index);
    if (!instance || !instance->transform) return smooth;
    return normal_to_world(*instance->transform, smooth);
}

// The bound handed to shading. A point's own error along the normal is not enough: intersection
// tests round relative to all the coordinates they subtract, not only those along the normal.
// A floor at y = 0.02 has tiny y and large x and z; a point on it is off by 1e-17 in y, and a test
// of a shadow ray from 2e-17 above it, grazing along x, rounds its t at 1e-16 of x: it finds the
// floor again at t = 0 (seen on scenes/stage6/acne-scale-1.test, whose slab is two coplanar
// triangles). So every coordinate gets the largest coordinate's bound, times kTestRounding for
// the tests' own roundings. renderer/tests/surface_point_test.cpp leaves every kind of primitive,
// at every scale, with grazing and steep rays: without the widening, 50 to 70 of its 20,000 leaving
// rays per scene find the slab again; with it (already at kTestRounding = 1), none does. 4 leaves
// room for triangle tests that round more than the reference's.
constexpr double kTestRounding = 4.0;

Vec3 covering_tests(const Vec3& error) {
    return Vec3(kTestRounding * std::max({error.x, error.y, error.z}));
}

}  // namespace

SurfacePoint surface_point(const RenderScene& render_scene, const Ray& ray,
                           const PrimitiveHit& hit) {
    const PlacedPoint placed = place(render_scene, ray, hit);
    SurfacePoint point;
    point.position = placed.position;
    point.error = covering_tests(placed.error);
    point.to_eye = -glm::normalize(ray.direction);
    point.normal = glm::dot(hit.hit.normal, point.to_eye) < 0.0 ? -hit.hit.normal : hit.hit.normal;
    point.shading_normal = point.normal;
    if (hit.kind == PrimitiveKind::triangle) {
        const std::int32_t vertex_normals =
            triangle_corners(render_scene, hit.index).vertex_normals;
        // Where the vertex normals cancel there is no smooth normal: the flat one shades.
        if (vertex_normals >= 0) {
            if (const std::optional<Vec3> smooth =
                    interpolated_normal(render_scene, hit.index, vertex_normals, hit.hit)) {
                point.shading_normal = glm::dot(*smooth, point.normal) < 0.0 ? -*smooth : *smooth;
            }
        }
    }
    return point;
}

}  // namespace raystep
