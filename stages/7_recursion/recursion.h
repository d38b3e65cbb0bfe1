#pragma once

#include <functional>
#include <optional>

#include "stages/2_rays/ray.h"
#include "stages/6_shading/shading.h"

namespace raystep {

// Stage 7: recursive ray tracing. Handout: docs/stage7.md.
//
// A mirror sends the eye ray on: what it shows is what the reflected ray sees, weighted by the
// specular colour Ks as the mirror's reflectance (the CSE167 format has no separate one):
//
//   I(ray) = local + Ks I(reflected ray),   the recursion cut after maxdepth bounces.

/// What the renderer finds where a ray lands: the point, its colour from stage 6 (shadows
/// included) and its reflectance.
struct ShadedHit {
    SurfacePoint point;
    Color local;
    Color reflectance;  ///< the material's specular colour, Ks
};

/// Finds and shades the nearest hit of a ray; nullopt when the ray leaves the scene.
using ShadeFunction = std::function<std::optional<ShadedHit>(const Ray&)>;

/// The mirror ray at a hit: the incoming direction -V reflected about the shading normal
/// (stage 1's reflect), leaving the surface by spawn_ray with the given offset, unbounded:
/// distance infinity, not a large number standing in for it.
Ray reflected_ray(const SurfacePoint& point, const RayOffset& offset);

/// What the ray sees: black when it misses; else the local colour plus the reflectance times
/// what the reflected ray sees, while bounces remain (`bounces_left`, maxdepth for an eye ray)
/// and the reflectance is not black. Black is exactly (0, 0, 0): a weak mirror reflects too,
/// however small its reflectance.
Color radiance(const ShadeFunction& shade, const Ray& ray, int bounces_left,
               const RayOffset& offset);

}  // namespace raystep
