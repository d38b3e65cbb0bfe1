#pragma once

#include <cstddef>
#include <optional>

#include "base/scene/scene.h"

namespace raystep {

// The answer the epsilon study (docs/stage6.md, "Measuring acne") scores shadow rays against:
// where a camera ray really meets the scene, and whether a point light really reaches that point.
//
// "Really" means computed in long double (64-bit significand, 11 bits more than the renderer's
// double) from the same double inputs, with every decision that comes within a relative 1e-12 of
// its boundary left undecided. The renderer's rounding is near 1e-16 relative, so a decided answer
// is right far beyond anything the renderer can do, and the undecided band (silhouettes, shadow
// edges, the terminator, each a 1e-12-wide sliver) holds next to no pixels. The scene may hold
// spheres, triangles and planes, and no transforms (their objects are taken as written): the acne
// scenes need no more.

/// A decision that may be too close to its boundary to take.
enum class Decided { no, yes, undecided };

/// A primitive of the scene, by kind and index in Scene's list of that kind.
struct PrimitiveRef {
    enum class Kind { sphere, triangle, plane } kind;
    std::size_t index;

    bool operator==(const PrimitiveRef& other) const {
        return kind == other.kind && index == other.index;
    }
};

/// The exact first hit of a ray: which primitive (nullopt on a miss), or undecided when a
/// silhouette or a near tie makes the primitive uncertain.
struct ExactHit {
    bool decided = true;
    std::optional<PrimitiveRef> primitive;
    long double t = 0;  ///< along the ray, when a primitive is hit
};

/// The first primitive the ray meets for t > 0.
ExactHit exact_first_hit(const Scene& scene, const Vec3& origin, const Vec3& direction);

/// Whether the point light at `light` reaches the point where the ray meets `hit`: yes when the
/// light is on the side of the surface the ray came from and no primitive crosses the segment
/// from the point to the light; no when either fails clearly; undecided in between.
Decided exact_light_reaches(const Scene& scene, const Vec3& origin, const Vec3& direction,
                            const ExactHit& hit, const Vec3& light);

}  // namespace raystep
