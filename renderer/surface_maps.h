#pragma once

#include <optional>

#include "base/scene/scene.h"
#include "renderer/render_scene.h"
#include "stages/11_surface_detail/surface_detail.h"
#include "stages/6_shading/shading.h"

namespace raystep {

/// Where a hit lies in its material's images, (u, v), and how the surface moves with them there,
/// dp/du and dp/dv in the world; nullopt derivatives where it has none (a sphere's poles, a
/// triangle whose uvs lie on a line). How each primitive has them: mapped_material below.
struct SurfaceUv {
    Vec2 uv;
    std::optional<SurfaceDerivatives> derivatives;
};

SurfaceUv surface_uv(const RenderScene& render_scene, const Ray& ray, const PrimitiveHit& hit);

/// What a hit's material's maps change there (docs/stage11.md), through stage 11's lookups at the
/// hit's (u, v): the material returned has its diffuse colour multiplied by the texture's, and
/// `point`'s shading normal is tilted by the normal map or the bump map, then turned to the side
/// of the geometric normal, which no map changes. A material without maps is returned as it is.
///
/// (u, v) and dp/du, dp/dv come from the primitive in its own frame: a triangle's `triuv` or
/// mesh `vt` coordinates (else its (beta, gamma)), a sphere's spherical angles (stage 11's
/// sphere_uv), a plane's position along two axes of its own, in scene units; the derivatives are
/// taken to the world by M. Where there is no tangent frame (dp/du along the normal, at a
/// sphere's poles), the normal is left unmapped.
Material mapped_material(const RenderScene& render_scene, const Ray& ray, const PrimitiveHit& hit,
                         const Material& material, SurfacePoint& point);

}  // namespace raystep
