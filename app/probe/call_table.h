#pragma once

#include <functional>
#include <map>
#include <string>

#include "app/protocol/probe_json.h"

namespace raystep::probe {

// What a probe can be asked: each call takes its arguments as JSON and returns its result as
// JSON, calling this build's stage functions (the submission's, or the reference's). Exceptions
// go through: the probe's loop reports them (grader/probe/README.md), and `raystep grade` answers
// its public cases with the same calls in process (call_reply.h).

using Call = std::function<Json(const Json& arguments)>;
using CallTable = std::map<std::string, Call>;

/// Every stage's calls (app/probe/<stage>_calls.h): what `raystep grade` answers a public case
/// with. Stage 4's structure as data and its timed workloads are for the grader's checks alone,
/// which a release does not run, so only the grader's probe has them
/// (grading/4_accel/accel_workloads.h).
CallTable stage_calls();

}  // namespace raystep::probe
