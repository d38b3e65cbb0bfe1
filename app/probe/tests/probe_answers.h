#pragma once

// Probe answers made by hand, for the tests of the judges (app/grade/, grader/grade/checks/).

#include "app/probe/probe_answer.h"
#include "app/protocol/probe_json.h"
#include "stages/2_rays/ray.h"

namespace raystep::testing {

/// The answer of a call that returned `value` (a number, a vector, a ray, ... in the protocol's
/// JSON).
inline grade::ProbeAnswer result_answer(const probe::Json& value) {
    grade::ProbeAnswer answer;
    answer.kind = grade::ProbeAnswer::Kind::result;
    answer.value = value;
    return answer;
}

/// The answer of a call that returned the number `x`, written as a double ("2.0"), as a probe
/// writes one, even where the test gives an integer.
inline grade::ProbeAnswer result_answer(double x) {
    return result_answer(probe::Json(x));
}

/// The answer of a call that returned the ray `r`.
inline grade::ProbeAnswer ray_answer(const Ray& r) {
    return result_answer(probe::ray(r));
}

}  // namespace raystep::testing
