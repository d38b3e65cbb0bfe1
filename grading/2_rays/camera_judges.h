#pragma once

#include "app/protocol/probe_json.h"
#include "base/math/types.h"

namespace raystep::grade {

/// "camera_ray": the result a list of one ray (a camera call asked for one pixel) whose origin is
/// within `origin_tolerance` of `origin` and whose direction is of unit length (unit_length,
/// value_text.h) and within `direction_tolerance` of `direction`, per coordinate, over t in
/// [0, inf]; a NaN anywhere fails. Its data is what build_judge (data_judge.h) reads back.
probe::Json camera_ray_judge(const Vec3& origin, double origin_tolerance, const Vec3& direction,
                             double direction_tolerance);

}  // namespace raystep::grade
