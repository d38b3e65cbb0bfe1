#pragma once

#include <string>
#include <vector>

#include "app/grade/expected_ray.h"
#include "app/protocol/probe_json.h"

namespace raystep::grade {

// The judges of stage 7's answers (recursion_judges.cpp): the mirror ray, and radiance over a
// scripted scene, every ray it asked about and the colour it added up. Each function below
// writes the judge's data, {"judge": NAME, ...}, which build_judge (data_judge.h) turns back
// into the judge. The expectations are double-doubles the grader's oracle decided with more bits
// than a double (grading/7_recursion/recursion_oracle.h), written with every bit
// (app/protocol/wide_json.h).

/// "mirror_ray": the result one ray as `expected` says; a NaN anywhere fails.
probe::Json mirror_ray_judge(const ExpectedRay& expected);

/// "unbounded_ray": the result a ray whose t_max is infinity, as reflected_ray's contract says,
/// not a large finite number standing in for it.
probe::Json unbounded_ray_judge();

/// "radiance": the result {"colour", "rays"}, the colour within `tolerance` of `colour` per
/// channel and the rays asked about, in order, each as its ExpectedRay says and no more or fewer.
probe::Json radiance_judge(const DoubleDoubleVec3& colour, const DoubleDoubleVec3& tolerance,
                           const std::vector<ExpectedRay>& rays);

/// An expected ray as these judges write it and read it back (strictly), whether a ray matches
/// it (a NaN anywhere fails), and how a report writes it: for other stages' judges of rays that
/// leave a surface as the mirror ray does (stage 9's refracted ray).
probe::Json expected_ray_json(const ExpectedRay& expected);
ExpectedRay expected_ray_from(const probe::Json& j);
bool ray_matches(const Ray& got, const ExpectedRay& expected);
std::string expected_ray_text(const ExpectedRay& expected);

}  // namespace raystep::grade
