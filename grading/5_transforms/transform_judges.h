#pragma once

#include <array>
#include <optional>

#include "app/protocol/probe_json.h"
#include "base/math/double_double_vec.h"
#include "base/math/types.h"

namespace raystep::grade {

// The judges of stage 5's answers (transform_judges.cpp): a matrix, a transform, a ray moved
// between frames and a hit on a transformed sphere, each against the expectation a grader's oracle
// decided with more bits than a double (grading/5_transforms/transform_oracle.h), kept in
// double-double and written whole (app/protocol/wide_json.h). Each function writes the judge's
// data, {"judge": NAME, ...}, which build_judge (data_judge.h) turns back into the judge. Points to
// a vector (point_to_world) and normals (normal_to_world) are near_wide_vec3's (value_judges.h).

/// "near_wide_matrix": the result a 4x4 matrix, each entry within its own `tolerance` of
/// `expected`'s, compared in double-double; a NaN fails. A failure names the first entry out of
/// tolerance and shows the whole matrix got.
probe::Json near_wide_matrix_judge(const DoubleDoubleMat4& expected,
                                   const DoubleDoubleMat4& tolerance);

/// "near_wide_transform": the result a transform whose matrix is within `matrix_tolerance` of
/// `matrix` entry by entry, and then whose inverse is within `inverse_tolerance` of `inverse`, as
/// near_wide_matrix judges one matrix.
probe::Json near_wide_transform_judge(const DoubleDoubleMat4& matrix,
                                      const DoubleDoubleMat4& matrix_tolerance,
                                      const DoubleDoubleMat4& inverse,
                                      const DoubleDoubleMat4& inverse_tolerance);

/// "singular_transform": the result a transform whose matrix is exactly `matrix` and whose
/// inverse has `inverse_diagonal` on the first three entries of its diagonal: exactly the given
/// double, or, where the entry is empty (a zero scale factor's reciprocal, 1 / 0), anything not
/// finite, which no finite stand-in passes for. The other entries of the inverse are free.
probe::Json singular_transform_judge(const Mat4& matrix,
                                     const std::array<std::optional<double>, 3>& inverse_diagonal);

/// "near_wide_ray": the result a ray whose origin and direction are each within their own
/// per-coordinate tolerance of the expected ones, compared in double-double (the direction as it
/// is, not normalized), and whose t_min and t_max are exactly the given ones; a NaN fails.
probe::Json near_wide_ray_judge(const DoubleDoubleVec3& origin,
                                const DoubleDoubleVec3& origin_tolerance,
                                const DoubleDoubleVec3& direction,
                                const DoubleDoubleVec3& direction_tolerance, double t_min,
                                double t_max);

/// "near_wide_hit" for a hit: the result a hit whose t is within `t_tolerance` of `t` and whose
/// normal has unit length (unit_length, value_text.h) and is within `normal_tolerance` of
/// `normal` per coordinate, compared in double-double; a miss or a NaN fails.
probe::Json near_wide_hit_judge(double t, double t_tolerance, const DoubleDoubleVec3& normal,
                                const DoubleDoubleVec3& normal_tolerance);

/// "near_wide_hit" for a miss: the result a miss (null); any hit fails.
probe::Json wide_miss_judge();

}  // namespace raystep::grade
