#pragma once

#include <optional>

#include "app/grade/error_bound_region.h"
#include "base/math/double_double_vec.h"

namespace raystep::grade {

// A ray that stage 7's judges expect (recursion_judges.h), as the grader's oracle decides it with
// more bits than a double (grading/7_recursion/recursion_oracle.h), kept in double-double. No JSON
// here: the oracle's own library includes this header.

/// A ray as the judges expect it: each coordinate within its tolerance and t_min exact; t_max
/// exact, except that where infinity is expected the largest double passes too, since no finite
/// t exceeds it and it admits the same hits (unbounded_ray_judge asks for infinity itself). Under
/// the error-bound rule the origin is judged by its region instead.
struct ExpectedRay {
    DoubleDoubleVec3 origin;
    DoubleDouble origin_tolerance;
    DoubleDoubleVec3 direction;
    DoubleDouble direction_tolerance;
    double t_min;
    double t_max;
    std::optional<ErrorBoundOrigin> region;
};

}  // namespace raystep::grade
