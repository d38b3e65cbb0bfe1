#pragma once

#include "renderer/render_scene.h"
#include "stages/6_shading/shading.h"

namespace raystep {

/// The point where `ray` meets the primitive of `hit` (from scene_closest_hit), as shading and
/// the rays leaving it need it.
///
/// The position is not ray.at(t). The t of a grazing ray carries a relative error of a few ulps
/// divided by the cosine of the angle of incidence, and ray.at(t) multiplies that by the length
/// of the ray: the point can land far off the surface, on either side, which is where shadow
/// acne comes from. Instead the point is rebuilt from the primitive, so that its distance to the
/// surface is a few ulps of the primitive's own coordinates (pbrt-v4, "Managing Rounding Error"):
/// on a triangle the barycentric combination of its vertices, on a sphere the hit pushed back
/// onto the sphere along its radius, on a plane the hit projected onto it; for a sphere or
/// triangle of an instance, that point in the instance's own frame taken to the world by M.
/// `error` bounds that distance, widened
/// to cover the rounding of intersection tests near the point (surface_point.cpp says why).
SurfacePoint surface_point(const RenderScene& render_scene, const Ray& ray,
                           const PrimitiveHit& hit);

}  // namespace raystep
