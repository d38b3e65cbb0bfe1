#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "stages/2_rays/ray.h"
#include "stages/3_intersect/intersect.h"
#include "stages/4_accel/aabb.h"

namespace raystep {

// The bench's rays, made here rather than by stage 2's camera: a student's stage-2 stubs must
// not stop the bench of their stage 4.

/// The box around every sphere and triangle of the list; empty for an empty list.
Aabb bench_bounds(const PrimitiveList& primitives);

/// The direction from the box centre to the camera of every primary-ray workload: above and to
/// the side, so that no face of a box-like scene is seen edge-on.
inline const Vec3 kBenchViewDirection{0.4, 0.5, 1.0};

/// The vertical field of view of that camera, in degrees.
inline constexpr double kBenchFieldOfView = 45.0;

/// width x height rays through the pixel centres of a pinhole camera looking at the box's centre
/// from direction kBenchViewDirection, with y up, at the distance where the box's bounding sphere
/// just fills the image height. Row by row from the top-left pixel; unit directions, t in
/// [0, inf). A non-empty box is required.
std::vector<Ray> primary_rays(const Aabb& box, int width, int height);

/// `count` incoherent rays: origins uniform on the sphere of radius twice the box's diagonal
/// around its centre, each aimed at a point uniform in the box; unit directions, t in [0, inf).
/// The same seed gives the same rays on every platform.
std::vector<Ray> incoherent_rays(const Aabb& box, std::size_t count, std::uint64_t seed);

}  // namespace raystep
