#include "renderer/surface_maps.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "stages/11_surface_detail/surface_detail.h"
#include "stages/5_transforms/transform.h"

namespace raystep {

namespace {

// The texture coordinates a triangle without its own take: (0, 0), (1, 0), (0, 1) at its
// vertices, so that (u, v) is the hit's (beta, gamma).
const VertexUvs kBarycentricUvs{{0, 0}, {1, 0}, {0, 1}};

SurfaceUv uv_on_triangle(const RenderScene& render_scene, const PrimitiveHit& hit) {
    const Triangle& shape = triangle_shape(render_scene, hit.index);
    VertexUvs uvs = kBarycentricUvs;
    const std::int32_t vertex_uvs = triangle_corners(render_scene, hit.index).vertex_uvs;
    if (vertex_uvs >= 0) uvs = render_scene.scene->vertex_uvs[static_cast<std::size_t>(vertex_uvs)];
    return {interpolate_uv(uvs.uv0, uvs.uv1, uvs.uv2, hit.hit.beta, hit.hit.gamma),
            surface_derivatives(shape.p0, shape.p1, shape.p2, uvs.uv0, uvs.uv1, uvs.uv2)};
}

// u = phi / (2 pi), v = 1 - theta / pi on a sphere of radius r, n = (-sin theta sin phi,
// cos theta, -sin theta cos phi): dp/du = 2 pi r (n.z, 0, -n.x) and dp/dv = pi r (-cos theta n.x /
// sin theta, sin theta, -cos theta n.z / sin theta), which has no direction at the poles.
SurfaceUv uv_on_sphere(const Sphere& sphere, const Vec3& object_point) {
    constexpr double kPi = glm::pi<double>();
    const Vec3 n = glm::normalize(object_point - sphere.center);
    const double r = sphere.radius;
    const double sin_theta = std::sqrt(n.x * n.x + n.z * n.z);
    if (!(sin_theta > 0.0)) return {sphere_uv(n), std::nullopt};
    const Vec3 dpdu = 2.0 * kPi * r * Vec3(n.z, 0.0, -n.x);
    const Vec3 dpdv = kPi * r * Vec3(-n.y * n.x / sin_theta, sin_theta, -n.y * n.z / sin_theta);
    return {sphere_uv(n), SurfaceDerivatives{dpdu, dpdv}};
}

// Two axes across the plane's normal, the first along the world axis least aligned with it made
// orthogonal to it; (u, v) is the point's offset from the plane's point along them.
SurfaceUv uv_on_plane(const Plane& plane, const Vec3& point) {
    const Vec3 n = glm::normalize(plane.normal);
    const Vec3 size = glm::abs(n);
    const Vec3 axis = size.x <= size.y && size.x <= size.z ? Vec3(1, 0, 0)
                      : size.y <= size.z                   ? Vec3(0, 1, 0)
                                                           : Vec3(0, 0, 1);
    const Vec3 u = glm::normalize(axis - glm::dot(axis, n) * n);
    const Vec3 v = glm::cross(n, u);
    const Vec3 offset = point - plane.point;
    return {{glm::dot(offset, u), glm::dot(offset, v)}, SurfaceDerivatives{u, v}};
}

// M's linear part applied to a direction of the object's frame.
Vec3 vector_to_world(const Transform& transform, const Vec3& v) {
    return Vec3(transform.matrix * Vec4(v, 0.0));
}

// The same lookups as at uv, with uv moved by whole periods of the wrap mode (one image for
// repeat, two for mirror) or held near the image for clamp: a plane's (u, v) grows with the
// distance to its point, and stage 11's contract asks for |u|, |v| <= 1000, so that its texel
// indices fit an int.
Vec2 reduced_uv(const Vec2& uv, WrapMode wrap) {
    switch (wrap) {
        case WrapMode::repeat:
            return uv - glm::floor(uv);
        case WrapMode::mirror:
            return uv - 2.0 * glm::floor(0.5 * uv);
        case WrapMode::clamp:
            return glm::clamp(uv, Vec2(-1.0), Vec2(2.0));
    }
    return uv;
}

Color lookup(const RenderScene& render_scene, std::int32_t map, const Vec2& uv) {
    const auto k = static_cast<std::size_t>(map);
    const WrapMode wrap = render_scene.scene->textures[k].wrap;
    return texture_bilinear(render_scene.textures[k], reduced_uv(uv, wrap), wrap);
}

// The normal a normal map or a bump map gives the surface whose own (unflipped) normal is
// `normal`, or nullopt where the surface has no tangent frame there.
std::optional<Vec3> mapped_normal(const RenderScene& render_scene, const Material& material,
                                  const SurfaceUv& at, const Vec3& normal) {
    if (!at.derivatives) return std::nullopt;
    if (material.normal_map >= 0) {
        const std::optional<TangentFrame> frame = tangent_frame(*at.derivatives, normal);
        if (!frame) return std::nullopt;
        return normal_from_map(*frame, lookup(render_scene, material.normal_map, at.uv));
    }
    const auto k = static_cast<std::size_t>(material.bump_map);
    const WrapMode wrap = render_scene.scene->textures[k].wrap;
    const Vec2 slopes =
        height_slopes(render_scene.textures[k], reduced_uv(at.uv, wrap), wrap, material.bump_scale);
    // dp/du and dp/dv across the normal that shades: a smooth triangle's interpolated normal is
    // not the flat dp/du x dp/dv, and the bumped normal of a flat height map must be it.
    const Vec3& dpdu = at.derivatives->dpdu;
    const Vec3& dpdv = at.derivatives->dpdv;
    const SurfaceDerivatives across{dpdu - glm::dot(normal, dpdu) * normal,
                                    dpdv - glm::dot(normal, dpdv) * normal};
    return bump_normal(across, normal, slopes);
}

}  // namespace

SurfaceUv surface_uv(const RenderScene& render_scene, const Ray& ray, const PrimitiveHit& hit) {
    const Instance* instance = instance_of(render_scene, hit.kind, hit.index);
    const bool placed = instance && instance->transform;
    const Ray object_ray = placed ? ray_to_object(*instance->transform, ray) : ray;
    SurfaceUv found;
    switch (hit.kind) {
        case PrimitiveKind::triangle:
            found = uv_on_triangle(render_scene, hit);
            break;
        case PrimitiveKind::sphere:
            found = uv_on_sphere(render_scene.scene->spheres[hit.index].shape,
                                 object_ray.at(hit.hit.t));
            break;
        case PrimitiveKind::plane:
            found =
                uv_on_plane(render_scene.primitives.planes[hit.index], object_ray.at(hit.hit.t));
            break;
    }
    if (placed && found.derivatives) {
        found.derivatives->dpdu = vector_to_world(*instance->transform, found.derivatives->dpdu);
        found.derivatives->dpdv = vector_to_world(*instance->transform, found.derivatives->dpdv);
    }
    return found;
}

Material mapped_material(const RenderScene& render_scene, const Ray& ray, const PrimitiveHit& hit,
                         const Material& material, SurfacePoint& point) {
    if (!material.has_maps()) return material;
    const SurfaceUv at = surface_uv(render_scene, ray, hit);
    Material mapped = material;
    if (material.diffuse_map >= 0)
        mapped.diffuse *= lookup(render_scene, material.diffuse_map, at.uv);
    if (material.normal_map >= 0 || material.bump_map >= 0) {
        // Mapped from the surface's own side, so that its back shows the same dents, not bumps;
        // then turned to the eye, as the point's normals are.
        const Vec3 own = glm::dot(point.normal, hit.hit.normal) < 0.0 ? -point.shading_normal
                                                                      : point.shading_normal;
        try {
            if (const std::optional<Vec3> tilted = mapped_normal(render_scene, material, at, own)) {
                point.shading_normal = glm::dot(*tilted, point.normal) < 0.0 ? -*tilted : *tilted;
            }
        } catch (const std::domain_error&) {
            // A texel or a bump with no direction: the unmapped normal shades.
        }
    }
    return mapped;
}

}  // namespace raystep
