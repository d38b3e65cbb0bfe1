#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "app/grade/rubric.h"
#include "app/report/grade_report.h"
#include "grader/grade/probe_toolchain.h"

namespace raystep::grade {

/// GradeOptions::checks_time_limit unless given.
inline constexpr int kChecksTimeLimit = 360;

struct GradeOptions {
    std::filesystem::path submission;  ///< a folder or an archive of any kind, or anything at all
    std::filesystem::path output;      ///< the reports go here
    /// Where the work folder is made; empty: as work_parent_for(output) says (work_folder.h).
    std::filesystem::path work_parent;
    bool keep_work = false;  ///< keep the work folder after grading (--keep-work), to look into
    /// What one grade keeps for the next (--cache): the objects it compiled in cache/objects
    /// (object_cache.h), and with an eye_seed given, the reference's noisy renders from its eyes
    /// in cache/renders/eye-SEED (checks/kept_renders.h); empty: none.
    std::filesystem::path cache;
    int jobs = 1;                   ///< compiles and checks run this many at a time
    std::string only_check;         ///< run just this check (--check), for reproducing
    std::optional<int> only_stage;  ///< run just this stage's checks (--stage; 0: the pipeline)
    bool skip_speed = false;        ///< leave the speed checks out (--no-speed)
    bool only_speed = false;        ///< run just the speed checks (a batch's second pass)
    std::optional<std::size_t> only_case;  ///< and of it just this case (--case)
    /// The render checks' eyes (--eye-seed, GradingContext::eye_seed); unset: drawn for this grade.
    std::optional<std::uint64_t> eye_seed;
    std::filesystem::path reference_probe;
    std::string reproduce;  ///< how a reproduce command starts: "raystep-grade submission PATH"
    /// The wall-clock time a grade's checks may take (--checks-time-limit): a check that would
    /// start after it ends as timed out, with no points. A submission that sleeps waits out every
    /// check's own limit (20 s for most, 120 s for a render of sampled views) at no processor
    /// time, some 6 minutes a stage; so its grade ends within this and one check's limit, inside
    /// Gradescope's 10 minutes, and a batch's slot is not held for an hour. The model's whole
    /// grade takes 15 to 40 s (docs/measurements/grading-time.md).
    std::chrono::seconds checks_time_limit{kChecksTimeLimit};
};

/// Grades one submission: takes its manifest files (submission.h) into a fresh work folder
/// (work_folder.h), builds the probes its checks need (probe_builder.h), runs the checks
/// (checks/) and scores each by the rubric. Relative paths are taken from the current folder.
/// Nothing the submission is or does can stop it: whatever it holds, every check ends with an
/// outcome, and the report is complete (intake_problem says why files could not be taken).
/// Throws only for the grader's own problems (no toolchain, a rubric without an entry for a
/// check, an unknown --check, a work folder it cannot make).
GradeReport grade_submission(const GradeOptions& options, const Rubric& rubric,
                             const ProbeToolchain& toolchain);

}  // namespace raystep::grade
