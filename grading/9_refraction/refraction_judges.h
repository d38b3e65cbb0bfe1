#pragma once

#include <vector>

#include "app/grade/expected_ray.h"
#include "app/protocol/probe_json.h"
#include "stages/9_refraction/refraction.h"

namespace raystep::grade {

// The judges of stage 9's answers (refraction_judges.cpp): Snell's direction, the media, the
// refracted ray, and radiance over a fake scene. Each function below writes the judge's data,
// {"judge": NAME, ...}, which build_judge (data_judge.h) turns back into the judge. The
// expectations are double-doubles the grader's oracle decided with more bits than a double
// (grading/9_refraction/refraction_oracle.h); the Fresnel reflectances are single numbers, judged
// by near_wide_number (value_judges.h).

/// What a right answer may be where total internal reflection is in question: a direction,
/// nullopt, or (within rounding of the critical angle) either.
struct AllowedAnswers {
    bool direction = true;
    bool none = false;
};

/// "refraction": the result null where `allowed.none`, or a vector, each component within
/// `tolerance` of `direction`, where `allowed.direction`; a NaN anywhere fails.
probe::Json refraction_judge(const AllowedAnswers& allowed, const DoubleDoubleVec3& direction,
                             const DoubleDouble& tolerance);

/// "media": the result exactly `expected`, the same solids with the same indices in the same
/// order.
probe::Json media_judge(const MediumStack& expected);

/// "refracted_ray": the result null where `allowed.none`, or a ray as `ray` says (stage 7's
/// matching, recursion_judges.h) where `allowed.direction`.
probe::Json refracted_ray_judge(const AllowedAnswers& allowed, const ExpectedRay& ray);

/// "refraction_radiance": the result {"colour", "rays"}, the colour within `tolerance` per
/// channel, and the rays asked about matching `rays` one to one in any order: a recursion may
/// follow the refracted ray first, or walk the tree with a stack of its own.
probe::Json refraction_radiance_judge(const DoubleDoubleVec3& colour,
                                      const DoubleDoubleVec3& tolerance,
                                      const std::vector<ExpectedRay>& rays);

}  // namespace raystep::grade
