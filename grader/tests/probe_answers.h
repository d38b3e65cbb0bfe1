#pragma once

// Probe answers made by hand, for the tests of the grader's judging.

#include <string>

#include "grader/grade/probe_client.h"

namespace raystep::testing {

/// The answer of a call that returned the number `x`.
inline grade::ProbeAnswer result_answer(double x) {
    grade::ProbeAnswer answer;
    answer.kind = grade::ProbeAnswer::Kind::result;
    answer.value = x;
    return answer;
}

}  // namespace raystep::testing
