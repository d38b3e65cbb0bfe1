#pragma once

#include <string>

#include "app/protocol/probe_json.h"

namespace raystep::grade {

/// One query for a probe: a call and its arguments (grader/probe/README.md).
struct ProbeQuery {
    std::string call;
    probe::Json args;
};

/// What the probe said to one query: read from a sandboxed probe's answer channel by the grader,
/// or from the same call table in process by `raystep grade` (call_reply.h).
struct ProbeAnswer {
    enum class Kind {
        result,           ///< `value` holds it
        not_implemented,  ///< a stub; `message` is its text
        threw,            ///< `exception_type` and `message`
        unanswered,       ///< the probe ended (crash, timeout, flood) before answering
        malformed,  ///< not what the protocol says; `message` has the line and its likely cause
    } kind = Kind::unanswered;
    probe::Json value;
    std::string exception_type;
    std::string message;
};

}  // namespace raystep::grade
