#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "stages/2_rays/ray.h"
#include "stages/7_recursion/recursion.h"

namespace raystep {

// Stage 9: refraction. Handout: docs/stage9.md.
//
// At the surface of glass or water a ray splits: a share F of its light is reflected, the rest
// goes through, bent by Snell's law, n1 sin(theta1) = n2 sin(theta2). F, the Fresnel reflectance,
// grows from about 4% head-on (glass in air) to 1 at grazing angles, and is 1 whenever no
// refracted direction exists (total internal reflection, leaving the denser medium beyond the
// critical angle). With Kt the surface's transmission colour and Ks its mirror colour:
//
//   I(ray) = local + (Ks + Kt F) I(reflected ray) + Kt (1 - F) I(refracted ray),
//
// the recursion cut after maxdepth bounces, as in stage 7.
//
// The indices on each side come from the media the ray is in: it enters a solid through a
// surface whose outward normal faces it, leaves through one that faces away; solids may nest
// (an ice cube in water in a glass) or overlap, so a ray keeps the list of the solids it is in.

/// Snell's law in vector form. `incident` is the unit direction of travel, `normal` the unit
/// normal on the incident side (incident . normal <= 0), eta = n1 / n2 the ratio of the indices
/// on the incident and the far side. The unit refracted direction, on the far side; nullopt
/// under total internal reflection (sin^2(theta2) = eta^2 (1 - cos^2(theta1)) > 1).
std::optional<Vec3> refract(const Vec3& incident, const Vec3& normal, double eta);

/// The Fresnel reflectance of a dielectric interface for unpolarised light, the mean of the s
/// and p reflectances, with cos_incident = cos(theta1) in [0, 1] on the side of index n1 and
/// n2 the far side's index. 1 under total internal reflection. A cosine computed as V . N may
/// round a little above 1: it counts as 1 (a sine taken as sqrt(1 - cos^2) must not be NaN).
double fresnel_exact(double cos_incident, double n1, double n2);

/// Schlick's approximation R0 + (1 - R0)(1 - cos)^5, R0 = ((n1 - n2)/(n1 + n2))^2, with cos the
/// cosine on the less dense side: cos(theta1) when n1 <= n2, cos(theta2) when leaving a denser
/// medium, and 1 under total internal reflection. cos_incident as for fresnel_exact.
double fresnel_schlick(double cos_incident, double n1, double n2);

/// One solid a ray is inside: which object (the renderer's numbering) and its index.
struct Medium {
    std::uint32_t solid;
    double index;
    bool operator==(const Medium& other) const {
        return solid == other.solid && index == other.index;
    }
};

/// The solids a ray is inside, in the order it entered them; the last one entered is the medium
/// it travels in. Empty is air, of index 1.
using MediumStack = std::vector<Medium>;

/// The index of the medium the ray travels in: the last solid's, 1 when it is in none.
double current_index(const MediumStack& inside);

/// The stack after the ray crosses the surface of `solid`: entering adds it at the end; leaving
/// removes its latest entry from wherever it is (overlapping solids are left in any order), and
/// leaving a solid the stack does not hold (a ray that started inside it) changes nothing.
MediumStack after_crossing(const MediumStack& inside, const Medium& solid, bool entering);

/// The refracted ray at a hit: refract(-V, N, n1 / n2) with N the shading normal, leaving the
/// surface by stage 6's spawn_ray with `offset` (so it starts on the far side), unbounded;
/// nullopt under total internal reflection.
std::optional<Ray> refracted_ray(const SurfacePoint& point, double n1, double n2,
                                 const RayOffset& offset);

/// What the renderer finds where a ray lands, for stage 9: stage 7's shaded hit, the surface's
/// transmission colour, and which solid it bounds and whether the ray is entering it.
struct MediumHit {
    ShadedHit shaded;
    Color transmission;  ///< Kt: black for an opaque surface
    Medium solid;        ///< the solid the surface bounds and its index
    bool entering;       ///< the ray arrives from outside: its direction is against the
                         ///< outward normal
};

/// Finds and shades the nearest hit of a ray; nullopt when the ray leaves the scene.
using MediumShadeFunction = std::function<std::optional<MediumHit>(const Ray&)>;

/// I(ray) as above: black on a miss; at a hit, local plus, while bounces remain, the reflected
/// ray (stage 7's reflected_ray) weighted Ks + Kt F and the refracted ray weighted Kt (1 - F),
/// in the media after the crossing. F is fresnel_schlick when `schlick`, else fresnel_exact,
/// with n1 the index the ray travels in, n2 the index beyond the surface and cos(theta1) = V . N
/// with N the shading normal, the normal refracted_ray bends about. Reflected rays stay
/// in `inside`. A weight that is exactly black traces no ray.
Color radiance_with_refraction(const MediumShadeFunction& shade, const Ray& ray, int bounces_left,
                               const MediumStack& inside, bool schlick, const RayOffset& offset);

}  // namespace raystep
