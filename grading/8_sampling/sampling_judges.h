#pragma once

#include <vector>

#include "app/protocol/probe_json.h"
#include "base/math/types.h"

namespace raystep::grade {

// The judges of stage 8's deterministic answers that are lists of points (sampling_judges.cpp):
// each function writes the judge's data, {"judge": NAME, ...}, which build_judge (data_judge.h)
// turns back into the judge. Rays through film points are camera_ray's (camera_judges.h), light
// samples light_sample's (shading_judges.h); the random answers are judged by their
// distributions, in the grader only (grading/8_sampling/stage8_statistics.cpp).

/// "point_set": the result the points `expected` in any order, each coordinate within
/// `tolerance`; a NaN fails.
probe::Json point_set_judge(const std::vector<Vec2>& expected, double tolerance);

/// "sample_points": the result a list with one list of points per stream asked, each of `count`
/// points in [0, 1)^2; a NaN fails.
probe::Json sample_points_judge(int count);

}  // namespace raystep::grade
