#pragma once

#include <string>

#include "app/grade/error_bound_region.h"
#include "app/protocol/probe_json.h"
#include "base/math/double_double_vec.h"
#include "base/math/types.h"
#include "stages/6_shading/shading.h"

namespace raystep::grade {

// The judges of stage 6's answers that are more than one value (shading_judges.cpp): each
// function below writes the judge's data, {"judge": NAME, ...}, which build_judge (data_judge.h)
// turns back into the judge. Colours are near_wide_vec3's (value_judges.h). The expectations are
// double-doubles a grader's oracle decided with more bits than a double
// (grading/6_shading/shading_oracle.h, grader/oracle/error_bound_origin.h), written with every bit
// (app/protocol/wide_json.h).

/// `light from (...) at d, intensity (...)`, as a report writes a light sample.
std::string light_sample_text(const LightSample& l);

/// An error-bound region as a judge's data, {"point", "normal", "offset", "ulps"}, and back
/// (stage 7's mirror ray leaves by the same rule); reading is strict and throws on a missing or
/// ill-typed field.
probe::Json region_json(const ErrorBoundOrigin& region);
ErrorBoundOrigin region_from(const probe::Json& j);

/// "light_sample": the result a light sample whose direction is within `direction_tolerance` of
/// `direction` per coordinate, whose intensity is within `intensity_tolerance` of `intensity` per
/// channel, and whose distance is within `distance_tolerance` of `distance`, or exactly infinity
/// when `distance` is infinite (a directional light). A NaN anywhere fails.
probe::Json light_sample_judge(const DoubleDoubleVec3& direction, double direction_tolerance,
                               const DoubleDouble& distance, const DoubleDouble& distance_tolerance,
                               const DoubleDoubleVec3& intensity,
                               const DoubleDoubleVec3& intensity_tolerance);

/// What every offset rule keeps of a ray that leaves a surface (spawn_ray, shadow_ray): the
/// direction, within `tolerance` per coordinate (renormalizing a unit vector moves it a few
/// ulps), and the end, exactly `t_max`.
struct LeavingDirection {
    Vec3 direction;
    double tolerance = 0.0;
    double t_max = 0.0;
};

/// "leaving_ray", rule "along_ray": the origin exactly `origin` (the point itself) and t_min
/// exactly `t_min` (the epsilon).
probe::Json along_ray_judge(const Vec3& origin, double t_min, const LeavingDirection& end);

/// "leaving_ray", rule "along_normal": the origin within `tolerance` of `origin` per coordinate,
/// t_min exactly 0.
probe::Json along_normal_judge(const DoubleDoubleVec3& origin, const DoubleDoubleVec3& tolerance,
                               const LeavingDirection& end);

/// "leaving_ray", rule "error_bound": the origin in `region` (error_bound_region.h), t_min
/// exactly 0.
probe::Json error_bound_judge(const ErrorBoundOrigin& region, const LeavingDirection& end);

}  // namespace raystep::grade
