#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include "base/scene/shapes.h"
#include "stages/2_rays/ray.h"

namespace raystep {

// A ray case: one ray against one or more primitives, each with the exact oracle's answer. The
// unit of stage 3's checks: `raystep check` runs the configured build on case files, and the
// grader runs a submission on cases it generates. The answers come from grader/oracle (exact
// arithmetic); nothing here computes them. docs/case-files.md describes the file format.

/// What the exact oracle says about one ray and one primitive.
struct Expectation {
    bool hit = false;  ///< the exact answer, under intersect.h's contract
    /// The ray passes within rounding of a decision boundary (an edge, tangency, being parallel,
    /// t_min or t_max): a correct double-precision test may answer either way, so either passes.
    bool near_boundary = false;
    /// Where the ray meets the surface, the exact t rounded to the nearest double: of the hit, or
    /// for a near-boundary miss of the crossing a nearby ray would hit. NaN when there is none (a
    /// miss that is not near a boundary, a ray parallel to the plane).
    double t = std::numeric_limits<double>::quiet_NaN();
    /// A reported t passes when it is within this distance of `t`: the rounding a backward-stable
    /// double-precision test may make, scaled by the problem (docs/case-files.md).
    double t_tolerance = 0.0;
    /// The unit geometric normal where the ray meets the surface (as intersect.h defines it),
    /// rounded; NaN when `t` is NaN. A reported normal passes when it is unit length and within
    /// `normal_tolerance` of this one (|reported - expected| <= normal_tolerance).
    Vec3 normal{std::numeric_limits<double>::quiet_NaN()};
    double normal_tolerance = 0.0;
    /// Triangles: the exact barycentrics of that point, rounded; NaN otherwise. Each reported one
    /// passes within `barycentric_tolerance`.
    double beta = std::numeric_limits<double>::quiet_NaN();
    double gamma = std::numeric_limits<double>::quiet_NaN();
    double barycentric_tolerance = 0.0;
    /// A second hit that also passes, with its own normal: a sphere's far root, when the near root
    /// lies within rounding of t_min (a ray starting on the surface may see the near root or
    /// not). NaN otherwise. It has the same t_tolerance and normal_tolerance.
    double t_alternative = std::numeric_limits<double>::quiet_NaN();
    Vec3 normal_alternative{std::numeric_limits<double>::quiet_NaN()};
};

using CaseShape = std::variant<Sphere, Triangle, Plane>;

struct CasePrimitive {
    CaseShape shape;
    Expectation expected;
};

struct RayCase {
    std::uint64_t index = 0;  ///< the case's number in its family
    Ray ray;
    std::vector<CasePrimitive> primitives;
    /// The primitives are neighbours in a closed mesh (they share an edge or a vertex) and all face
    /// the ray from the same side, so together they cover a neighbourhood of where it passes: when
    /// the exact ray meets any of them, at least one must report a hit, near a boundary or not.
    bool watertight = false;
};

/// A named, seeded family of cases: the family and the seed reproduce every case.
struct CaseFamily {
    std::string name;
    std::uint64_t seed = 0;
    std::string description;  ///< one line: what the family tests
    std::vector<RayCase> cases;
};

}  // namespace raystep
