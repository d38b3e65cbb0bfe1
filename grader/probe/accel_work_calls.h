#pragma once

#include "app/probe/call_table.h"

namespace raystep::probe {

/// Stage 4's work calls (accel_work_calls.cpp): a structure's primitive tests per ray, and its
/// timed workloads. Only in the grader's probe, which is linked to count the tests
/// (stage3_test_count.h); the structure's answers alone are app/probe's (add_accel_calls).
void add_accel_work_calls(CallTable& table);

}  // namespace raystep::probe
