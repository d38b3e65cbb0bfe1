#pragma once

#include <cstddef>
#include <cstdint>

#include "renderer/render_scene.h"
#include "stages/9_refraction/refraction.h"

namespace raystep {

// Which solid a surface bounds, for stage 9's media (a MediumStack holds solids by number).
// A refracted ray must leave through a surface of the solid it entered, so every surface of one
// closed object needs one number:
// - a sphere is a solid of its own, numbered by its place in Scene::spheres;
// - the triangles of one `mesh` file are one solid, and each `instance` of a defined mesh is
//   another (two placements of one glass are two glasses);
// - loose `tri` and `trinormal` triangles carry no grouping in the file, so those under one
//   material are taken as one solid: a scene builds a glass box from triangles by giving its
//   faces their own material, and two boxes of one glass that never overlap lose nothing by
//   sharing a number, since a ray leaves one before it enters the other;
// - a plane bounds a half-space, a solid of its own.
// The numbers run in that order: spheres, meshes, mesh instances, materials, planes.

/// The solid that the surface of primitive `index` of kind `kind` bounds (the numbering of
/// scene_closest_hit's hits).
std::uint32_t solid_of(const RenderScene& render_scene, PrimitiveKind kind, std::size_t index);

/// Stage 9's view of a hit surface: the solid it bounds, with its material's index.
Medium medium_of(const RenderScene& render_scene, const PrimitiveHit& hit);

/// Whether the ray arrives from outside the solid, against its outward normal (a sphere's
/// outward normal, a triangle's winding normal: the hit's normal before surface_point turns it
/// towards the ray).
bool entering(const Ray& ray, const PrimitiveHit& hit);

}  // namespace raystep
