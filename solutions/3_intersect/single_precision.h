#pragma once

// The reference tests in single precision, for the speed-against-error study
// (`raystep-reference bench --pareto`, docs/stage3.md): what a renderer that stores its scene in
// float gets. The ray and the shapes are rounded to float once, every operation runs in float,
// and the answer comes back in double, so that the study scores both precisions against the same
// exact answers. The renderer never uses them.

#include <optional>

#include <glm/vec3.hpp>

#include "stages/3_intersect/intersect.h"

namespace raystep {

/// A ray rounded to float. t_max = inf stays inf.
struct FloatRay {
    glm::vec3 origin;
    glm::vec3 direction;
    float t_min;
    float t_max;

    explicit FloatRay(const Ray& ray)
        : origin(ray.origin),
          direction(ray.direction),
          t_min(static_cast<float>(ray.t_min)),
          t_max(static_cast<float>(ray.t_max)) {}
};

struct FloatTriangle {
    glm::vec3 p0;
    glm::vec3 p1;
    glm::vec3 p2;

    explicit FloatTriangle(const Triangle& tri) : p0(tri.p0), p1(tri.p1), p2(tri.p2) {}
};

struct FloatSphere {
    glm::vec3 center;
    float radius;

    explicit FloatSphere(const Sphere& sphere)
        : center(sphere.center), radius(static_cast<float>(sphere.radius)) {}
};

struct FloatPlane {
    glm::vec3 point;
    glm::vec3 normal;

    explicit FloatPlane(const Plane& plane) : point(plane.point), normal(plane.normal) {}
};

/// The same contracts as their double namesakes in intersect.h and intersect_methods.h, with
/// the accuracy of float.
std::optional<Hit> intersect_triangle_projection_float(const Ray& ray, const Triangle& triangle);
std::optional<Hit> intersect_triangle_halfspaces_float(const Ray& ray, const Triangle& triangle);
std::optional<Hit> intersect_triangle_cramer_float(const Ray& ray, const Triangle& triangle);
std::optional<Hit> intersect_triangle_moller_trumbore_float(const Ray& ray,
                                                            const Triangle& triangle);
std::optional<Hit> intersect_triangle_watertight_float(const Ray& ray, const Triangle& triangle);
std::optional<Hit> intersect_sphere_float(const Ray& ray, const Sphere& sphere);
std::optional<Hit> intersect_plane_float(const Ray& ray, const Plane& plane);
std::optional<Hit> intersect_sphere_textbook_float(const Ray& ray, const Sphere& sphere);
std::optional<Hit> intersect_sphere_stable_roots_float(const Ray& ray, const Sphere& sphere);

}  // namespace raystep
