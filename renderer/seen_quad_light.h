#pragma once

#include <optional>

#include "base/scene/scene.h"
#include "stages/2_rays/ray.h"
#include "stages/4_accel/traversal.h"

namespace raystep {

// In the CSE168 dialect a quad light is seen as well as lighting the scene, as that course draws
// it (scene.h, SceneDialect). Only camera rays see it here: the lights are not in the BVH, where a
// shadow ray aimed at a light sample would meet the light itself at its end, so a quad light casts
// no shadow. A CSE167 scene's lights stay unseen.

/// What a camera ray sees of a quad light: the radiance from its emitting side (the side
/// ac x ab points to), black from behind, as a surface of no other colour would look.
struct SeenQuadLight {
    const QuadLight* light = nullptr;
    double t = 0.0;  ///< where the ray meets it
    Color colour;
};

/// The nearest quad light that the ray meets before its nearest surface `hit` (none: anywhere
/// along it), in a scene of the CSE168 dialect; nullopt in a CSE167 scene and where none is
/// nearer. Each light is the two triangles a, a + ab, a + ab + ac and a, a + ab + ac, a + ac,
/// tested by stage 3's intersect_triangle.
std::optional<SeenQuadLight> seen_quad_light(const Scene& scene, const Ray& ray,
                                             const std::optional<PrimitiveHit>& hit);

}  // namespace raystep
