#pragma once

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "grader/grade/probe_toolchain.h"
#include "grader/grade/submission.h"

namespace raystep::grade {

/// A probe built from a submission, or why there is none.
struct BuiltProbe {
    std::optional<std::filesystem::path> program;
    std::string
        failure;  ///< what stopped it: missing files, the compiler's or linker's first lines
};

/// Which probes a grade needs: the checks it runs decide (`--stage 3` needs one).
struct ProbesNeeded {
    std::set<int> stages;    ///< stage N from the submission, the reference for the rest
    bool pipeline = false;   ///< every stage from the submission
    bool reference = false;  ///< the reference probe, which the speed checks time
};

/// The probes of one submission: for each stage needed, that stage from the submission and the
/// rest from the reference (so that a stage that does not compile costs that stage only), the
/// whole pipeline, every stage from the submission, and a copy of the reference probe.
struct ProbeSet {
    std::vector<std::pair<int, BuiltProbe>> stages;  ///< by stage number, in order
    BuiltProbe pipeline;
    BuiltProbe reference;
    /// The image library module, copied into a folder of its own that the sandbox's user can
    /// read (work/image-library), which every probe is told to load a scene's textures from:
    /// without bubblewrap, the folders of the probes and of the build are shut to that user.
    std::filesystem::path image_library;
    double seconds = 0.0;

    /// The probe of stage `number`; one that was not needed reads "not built".
    const BuiltProbe& stage(int number) const;
};

/// How much building one submission may take. A stage's compile time and output are totals over
/// its files, so that splitting a slow or bloated stage into many files gains nothing.
struct BuildBudget {
    /// Wall-clock seconds for compiling all of a stage's files: forty times what the reference's
    /// slowest stage takes on one core (3 s; `time g++ -O3 -std=c++17 -I. -c solutions/4_accel/
    /// *.cpp`), room for a loaded machine and any student's code, and an end for a template bomb.
    double compile_seconds_per_stage = 120.0;
    /// Bytes the compiler may write for a stage's objects: the reference's seven stages take
    /// 0.2 MiB together.
    std::uintmax_t compile_bytes_per_stage = std::uintmax_t{64} << 20;
    /// Bytes one linked probe may take: the reference probe is under 1 MiB.
    std::uintmax_t link_bytes_per_probe = std::uintmax_t{128} << 20;
};

/// Builds the probes `needed` in `work`, which must be empty and searchable by the sandbox's user
/// (grade_submission makes it so):
/// - work/include: the headers of base/ and stages/ (no solutions, no studies, no grader); each
///   stage's files are compiled there with the reference's flags, each compile in the sandbox
///   with only that tree, the precompiled header, the stage's sources and its own output folder
///   in view, `jobs` stages at a time;
/// - work/precompiled: the precompiled header (probe_precompiled.h) that every such compile takes
///   first, where the build made one;
/// - work/link: what the links read, copied out of the build tree (the probe's own objects, the
///   libraries below the stages, each reference stage in a folder of its own), so that each link
///   sees only the reference stages its probe takes; removed once the probes are linked, before
///   any of them runs;
/// - work/probes/NAME/probe: each probe alone in its folder, which is all of the probes a run of
///   it is shown (probe_client.h). The folders are the grader's, the programs executable but not
///   readable by the sandbox's user; without bubblewrap work/probes itself is shut to that user,
///   and the sandbox executes a probe through a descriptor.
/// Compiler and linker output is kept to its first lines; a budget that runs out is named in the
/// failure. With an `object_cache` folder, a file compiled before with the same inputs is taken
/// from there instead (object_cache.h).
ProbeSet build_probes(const Submission& submission, const ProbeToolchain& toolchain,
                      const std::filesystem::path& reference_probe,
                      const std::filesystem::path& work, const ProbesNeeded& needed, int jobs,
                      const std::filesystem::path& object_cache = {},
                      const BuildBudget& budget = {});

}  // namespace raystep::grade
