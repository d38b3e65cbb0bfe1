#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grader/sandbox/sandbox.h"

namespace raystep::grade::testing {

// What the sandbox's tests share: the hostile programs built beside them, small limits, temporary
// folders, and a run that also says how long it took and what it left behind.

/// How long after its wall-clock limit a run may take to come back: the kill, the reaping and
/// bubblewrap's teardown. The bound is the wall limit, which run_sandboxed enforces by its own
/// clock, rather than a fixed time: on a busy machine a run held to its CPU limit can take several
/// times that in wall time, and that is the sandbox working, not failing.
inline constexpr double kReturnGraceSeconds = 5.0;

/// The path of a program under grader/sandbox/tests/hostile_programs/ ("segfault", "echo").
std::string hostile(const std::string& name);

/// Small limits (1 s of CPU, 3 s of wall clock, 256 MiB of address space, 16 processes, 1 MiB of
/// output), the hostile programs' folder read-only, and bubblewrap or not.
SandboxPolicy test_policy(bool isolate);

/// False, with a warning, when the test asks for bubblewrap and this machine cannot make one.
bool can_run(bool isolate);

/// False, with a warning, when nothing stands between a program and the files of the user running
/// the tests: no bubblewrap, and a grader that is not root, so that the program keeps its user.
bool files_protected(bool isolate);

struct HostileRun {
    SandboxRun run;
    double seconds = 0.0;             ///< run_sandboxed's own wall time, as its caller sees it
    double wall_limit_seconds = 0.0;  ///< the policy's wall-clock limit
    int left_behind = 0;  ///< processes of the run still there (a second after it returned)
};

/// What every run must show, however it ended: isolated as asked, back within its wall-clock limit
/// and kReturnGraceSeconds, nothing left running.
void check_contained(const HostileRun& hostile_run, bool isolate);

/// Makes this test process a child subreaper (Linux): every process that a run leaves behind,
/// and every zombie, then becomes a child of ours, where processes_left_behind sees it.
void adopt_orphans();

/// Reaps the zombies handed to us, then counts the processes that still descend from this one,
/// waiting up to a second for killed ones to go.
int processes_left_behind();

/// adopt_orphans, run_sandboxed, timed, then processes_left_behind.
HostileRun run_hostile(const std::vector<std::string>& argv, const std::string& input,
                       const SandboxPolicy& policy);

/// A new folder under /tmp with `mode` (0755 lets the sandbox's user in), removed with what is in
/// it at the end.
class TempFolder {
  public:
    explicit TempFolder(unsigned mode);
    ~TempFolder();
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;

    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

/// The text of a file; empty when it cannot be read.
std::string read_text(const std::filesystem::path& path);

/// The message of the std::runtime_error that run_sandboxed throws for `argv` under `policy`;
/// empty when it throws none.
std::string start_error(const std::vector<std::string>& argv, const SandboxPolicy& policy);

}  // namespace raystep::grade::testing
