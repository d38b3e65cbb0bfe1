#pragma once

#include <string>

#include "app/probe/call_table.h"
#include "app/probe/probe_answer.h"

namespace raystep::probe {

// One query answered by a call table, the same way in the grader's sandboxed probe
// (grader/probe/probe_main.cpp, which writes the reply as a line) and in `raystep grade`, which
// answers the student's own build in process: a stub, an exception and a result each become the
// reply the protocol names (grader/probe/README.md), and a reply is read back into a ProbeAnswer
// by one function on both sides.

/// The line a probe's main writes on its answer channel before it reads a query: the grader sends
/// the queries only once it has come (grader/probe/README.md).
inline constexpr const char* kReadyLine = R"({"ready":true})";

/// The reply to `query` ({"id", "call", "args"}): {"id", "result"}, {"id", "not_implemented"}
/// for a NotImplemented, or {"id", "threw": {"type", "message"}} for any other exception, its
/// type one of the standard ones the contracts name or "other". Never throws.
Json reply_to(const CallTable& table, const Json& query);

/// A reply read back. `line` is the text it came as, quoted in the message when the reply is not
/// one of the three forms (a malformed answer).
grade::ProbeAnswer read_reply(const Json& reply, const std::string& line);

/// A reply the protocol does not allow: `line` (clipped) quoted, and the likely cause.
grade::ProbeAnswer malformed_reply(const std::string& line, const std::string& cause);

/// `query` answered by `table` in this process: read_reply(reply_to(...)).
grade::ProbeAnswer answer_in_process(const CallTable& table, const grade::ProbeQuery& query);

}  // namespace raystep::probe
