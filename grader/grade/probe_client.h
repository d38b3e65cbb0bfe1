#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/probe/probe_answer.h"
#include "grader/sandbox/sandbox.h"

namespace raystep::grade {

/// A probe run: the answers in query order, and how the run ended.
struct ProbeSession {
    std::vector<ProbeAnswer> answers;
    SandboxRun run;
};

/// Where a probe may look and how long it may run.
// Every check's workload takes the reference well under a second: ten seconds of processor is
// room for a slow but right submission, and a hostile one that never answers costs no more.
struct ProbeRunLimits {
    double cpu_seconds = 10.0;
    std::chrono::milliseconds wall{20000};
    std::size_t answer_bytes = 128u << 20;        ///< the answers read at most
    std::vector<std::filesystem::path> readable;  ///< e.g. the scenes a render call loads
    /// The image library module the probe reads a scene's textures through
    /// (ProbeSet::image_library), readable with its folder; empty: the probe's own candidates.
    std::filesystem::path image_library;
};

/// Sends the queries to one run of the probe (in the sandbox), which sees only the folder that
/// holds `program` (nothing else may be in it) and `limits.readable`, and reads its answers from
/// its answer channel (sandbox.h); what it prints on stdout is kept in run.output. Never throws for
/// what the probe does: a crash leaves the remaining answers `unanswered`, and run says why.
ProbeSession ask_probe(const std::filesystem::path& program, const std::vector<ProbeQuery>& queries,
                       const ProbeRunLimits& limits);

}  // namespace raystep::grade
