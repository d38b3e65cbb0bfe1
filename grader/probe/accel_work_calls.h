#pragma once

#include "app/probe/call_table.h"

namespace raystep::probe {

/// Stage 4's calls that only the grader's probe has (accel_work_calls.cpp): a structure handed
/// back as data, and its timed workloads on rays that change every pass. The structure's answers
/// are app/probe's (add_accel_calls).
void add_accel_work_calls(CallTable& table);

}  // namespace raystep::probe
