#pragma once

// The exact core of each primitive's oracle: the decision and the exact t, shared by the
// expectations (which add tolerances) and by the closest-hit oracle (which compares t's).

#include <optional>

#include "base/scene/shapes.h"
#include "grading/3_intersect/exact_kernel.h"
#include "stages/2_rays/ray.h"

namespace raystep::exact {

/// The exact t of a hit: a rational (triangles, planes), or a root of a t^2 + 2 b t + c = 0 with
/// disc = b^2 - a c (spheres), the smaller one or the larger.
struct HitTime {
    Number rational;
    bool is_root = false;
    Number a, b, c, disc;
    bool smaller = true;
};

/// The exact hit time under intersect.h's contract, or nullopt on an exact miss.
std::optional<HitTime> triangle_hit_time(const Ray& ray, const Triangle& triangle);
std::optional<HitTime> sphere_hit_time(const Ray& ray, const Sphere& sphere);
std::optional<HitTime> plane_hit_time(const Ray& ray, const Plane& plane);

/// The nearest double to an exact hit time.
double rounded(const HitTime& time);

/// The sign of t1 - t2, exact for rationals; for roots decided at 4096 bits, where two different
/// roots closer than 2^-4000 of their size count as equal.
int compare(const HitTime& t1, const HitTime& t2);

}  // namespace raystep::exact
