#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "grader/grade/probe_toolchain.h"
#include "grader/grade/submission.h"

namespace raystep::grade {

/// A probe built from a submission, or why there is none.
struct BuiltProbe {
    std::optional<std::filesystem::path> program;
    std::string failure;  ///< what stopped it: missing files, the compiler's or linker's first lines
};

/// The probes of one submission: for each stage, that stage from the submission and the rest from
/// the reference (so that a stage that does not compile costs that stage only), and the whole
/// pipeline, every stage from the submission.
struct ProbeSet {
    std::vector<std::pair<int, BuiltProbe>> stages;  ///< by stage number, in order
    BuiltProbe pipeline;
    double seconds = 0.0;

    const BuiltProbe& stage(int number) const;
};

/// Copies the headers of core/ and stages/ (and nothing else of the repository: no solutions, no
/// grader) into work/include, compiles each stage's files there with the reference's flags, each
/// compile in the sandbox with only that tree and its own output folder in view, `jobs` at a
/// time, then links the probes, also in the sandbox. Compiler and linker output is kept to its
/// first lines.
ProbeSet build_probes(const Submission& submission, const ProbeToolchain& toolchain,
                      const std::filesystem::path& work, int jobs);

}  // namespace raystep::grade
