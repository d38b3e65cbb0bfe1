#pragma once

#include <string>

#include "app/protocol/probe_json.h"
#include "base/math/double_double_vec.h"
#include "base/math/types.h"

namespace raystep::grade {

// The judges of answers that are one value (value_judges.cpp): each function below writes the
// judge's data, {"judge": NAME, ...}, which build_judge (data_judge.h) turns back into the judge.

/// "near_number": the result a number within `tolerance` of `expected` (absolute).
probe::Json near_number_judge(double expected, double tolerance);

/// "near_vec3": the result a vector, every component within `tolerance` of `expected`'s
/// (absolute); a NaN fails.
probe::Json near_vec3_judge(const Vec3& expected, double tolerance);

/// "near_wide_number": the result within `tolerance` of `expected`, both double-doubles (a grader's
/// oracle decided them with more bits than a double; app/protocol/wide_json.h keeps every bit),
/// compared in double-double; a NaN fails.
probe::Json near_wide_number_judge(const DoubleDouble& expected, const DoubleDouble& tolerance);

/// "near_wide_vec3": the same per component, each with its own tolerance; with `unit`, the
/// result must also have unit length (unit_length, value_text.h), as a normalized vector must.
probe::Json near_wide_vec3_judge(const DoubleDoubleVec3& expected,
                                 const DoubleDoubleVec3& tolerance, bool unit = false);

/// "threw": the call threw the named standard exception ("domain_error", ...).
probe::Json threw_judge(const std::string& type);

/// "frame": the result {"u", "v", "w"}, each component within `tolerance` of the expected
/// frame's; a NaN fails.
probe::Json frame_judge(const Vec3& u, const Vec3& v, const Vec3& w, double tolerance);

}  // namespace raystep::grade
