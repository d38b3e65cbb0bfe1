#pragma once

#include <optional>

#include "app/protocol/probe_json.h"
#include "base/math/types.h"
#include "stages/10_path_tracing/path_tracing.h"

namespace raystep::grade {

// The judges of stage 10's answers that no value judge (app/grade/value_judges.h) says. Each
// function below writes the judge's data, {"judge": NAME, ...}, which build_judge
// (app/grade/data_judge.h) turns back into the judge.

/// "frame_around": the result {"u", "v", "w"} an orthonormal frame whose w is `normal`: w within
/// `tolerance` of it per component, u and v of unit length and every two at right angles within
/// `tolerance`. Which u and v is left to the student: a sampler's directions are the same
/// distribution in any such frame.
probe::Json frame_around_judge(const Vec3& normal, double tolerance);

/// "roulette": the result null where `expected` is nullopt (the path stops), else a colour
/// within `tolerance` of it per channel.
probe::Json roulette_judge(const std::optional<Color>& expected, double tolerance);

/// "light_direction_sample": the result's direction within `direction_tolerance` per component,
/// its distance, density and radiance each within `relative` of the expected value's size;
/// where the expected density is 0 (the point on the light's plane), only the density and the
/// radiance are judged.
probe::Json light_direction_sample_judge(const LightDirectionSample& expected,
                                         double direction_tolerance, double relative);

}  // namespace raystep::grade
