#pragma once

#include <optional>

#include "app/protocol/probe_json.h"
#include "base/math/types.h"
#include "stages/11_surface_detail/surface_detail.h"

namespace raystep::grade {

// The judges of stage 11's answers that no value judge (app/grade/value_judges.h) says: a pair of
// texture coordinates, the surface's derivatives and the tangent frame, each component within an
// absolute tolerance of the grader's oracle (grading/11_surface_detail/surface_detail_oracle.h).
// Each function below writes the judge's data, {"judge": NAME, ...}, which build_judge
// (app/grade/data_judge.h) turns back into the judge. A NaN anywhere fails.

/// "near_vec2": the result (u, v), each within `tolerance` of `expected`'s.
probe::Json near_vec2_judge(const Vec2& expected, double tolerance);

/// "surface_derivatives": the result null where `expected` is nullopt (the uvs have no area),
/// else dp/du and dp/dv, each component within `tolerance`.
probe::Json surface_derivatives_judge(const std::optional<SurfaceDerivatives>& expected,
                                      double tolerance);

/// "tangent_frame": the result null where `expected` is nullopt (dp/du along the normal), else
/// the tangent, bitangent and normal, each component within `tolerance`.
probe::Json tangent_frame_judge(const std::optional<TangentFrame>& expected, double tolerance);

}  // namespace raystep::grade
