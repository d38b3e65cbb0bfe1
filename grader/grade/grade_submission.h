#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "grader/grade/probe_toolchain.h"
#include "grader/grade/rubric.h"
#include "grader/report/grade_report.h"

namespace raystep::grade {

struct GradeOptions {
    std::filesystem::path submission;  ///< a folder or a .zip
    std::filesystem::path output;      ///< the reports go here; work/ beneath holds the build
    int jobs = 1;                      ///< compiles and checks run this many at a time
    std::string only_check;            ///< run just this check (--check), for reproducing
    std::optional<int> only_stage;     ///< run just this stage's checks (--stage; 0: the pipeline)
    bool skip_speed = false;           ///< leave the speed checks out (--no-speed)
    std::optional<std::size_t> only_case;  ///< and of it just this case (--case)
    std::filesystem::path reference_probe;
    std::string reproduce;  ///< how a reproduce command starts: "raystep-grade submission PATH"
};

/// Grades one submission: takes its manifest files (submission.h), builds its probes
/// (probe_builder.h), runs every check (checks/) and scores each by the rubric. Nothing the
/// submission does can stop it: every check ends with an outcome, and the report is complete.
/// Throws only for the grader's own problems (no toolchain, a rubric without an entry for a
/// check, a submission path that is neither a folder nor a zip).
GradeReport grade_submission(const GradeOptions& options, const Rubric& rubric,
                             const ProbeToolchain& toolchain);

}  // namespace raystep::grade
