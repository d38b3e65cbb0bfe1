#pragma once

#include <map>
#include <string>
#include <vector>

namespace raystep::grade {

// What grading one submission found: the data every report (console, Gradescope, PrairieLearn,
// JUnit, HTML) is written from. Nothing here is computed by student code: raystep-grade fills it
// from the probes' raw answers and its own expected answers.

/// How a check ended: every check ends as one of these (ARCHITECTURE.md, "How a check ends").
enum class Outcome {
    passed,
    failed,           ///< answered, but wrong: see the counterexamples
    crashed,          ///< the probe died of a signal while answering
    timed_out,        ///< the probe ran past its CPU or wall-clock limit
    not_implemented,  ///< the stage's stub threw NotImplemented
    did_not_compile,  ///< the stage's files did not compile: see the compiler's first lines
};

/// "passed", "failed", "crashed", "timed out", "not implemented", "did not compile".
std::string outcome_name(Outcome outcome);

/// Who sees a check and when (the rubric says; Gradescope's names).
enum class Visibility { visible, hidden, after_due_date, after_published };

std::string visibility_name(Visibility visibility);

/// One input the submission got wrong, with what would reproduce it.
struct Counterexample {
    std::string input;      ///< the call or case, readable
    std::string expected;   ///< the grader's answer
    std::string got;        ///< the submission's answer
    std::string reproduce;  ///< the instructor's command that reruns exactly this case
    /// What a student can run in the student release to see this case again (a `raystep check`
    /// or `raystep trace` command, or the call written out); empty when there is none.
    std::string student_reproduce;
};

/// An image a render check made: reference, student and difference, beside the report.
struct RenderImages {
    std::string reference;  ///< paths relative to the report's folder
    std::string student;
    std::string difference;  ///< the heat map
};

struct CheckResult {
    std::string id;    ///< stable and unique: "stage3.oracle.shared-edges"
    int stage = 0;     ///< 1 to kLastStage; 0 for the whole pipeline
    std::string kind;  ///< "unit", "oracle", "render" or "speed"
    std::string name;  ///< what it checks, in words
    Outcome outcome = Outcome::failed;
    double score = 0.0;
    double max_score = 0.0;
    Visibility visibility = Visibility::visible;
    std::string summary;  ///< one line: "97 of 100 cases right; 3 false misses"
    std::vector<Counterexample> counterexamples;  ///< the first few
    std::map<std::string, double> metrics;        ///< e.g. "rmse", "psnr", "ratio"
    RenderImages images;                          ///< render checks only
    std::string details;  ///< longer text: a compiler's first lines, a crash's signal
    /// Wall-clock seconds the check took to run and judge (the build not included); checks run
    /// side by side, so the checks' seconds may add up to more than PhaseTimes::checks.
    double seconds = 0.0;
};

/// How long each phase of grading took, in seconds.
struct PhaseTimes {
    double intake = 0.0;
    double build = 0.0;
    double checks = 0.0;
    double reports = 0.0;
};

/// The last lecture's stage: stage 0 is the whole pipeline, 1 to kLastStage the lectures'
/// (ARCHITECTURE.md, "How a check ends").
inline constexpr int kLastStage = 11;

/// The order reports show the stages in: the lectures' 1 to kLastStage, then the whole pipeline
/// (0).
inline constexpr int kStageReportOrder[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 0};

/// One stage's line of a report's summary.
struct StageTally {
    int stage = 0;
    double score = 0.0;
    double max_score = 0.0;
    int checks = 0;
    int passed = 0;
};

struct GradeReport {
    std::string submission;  ///< as given on the command line
    std::string student;     ///< a name for the class summary: the folder's or zip's name
    /// Why the submission's files could not all be taken, in words (not an archive, over a
    /// budget, ...); empty when they were. Every report says it.
    std::string intake_problem;
    /// The work folder, when it was kept (--keep-work) to look into; empty otherwise.
    std::string work_folder;
    std::vector<CheckResult> checks;
    PhaseTimes times;
    double score() const;
    double max_score() const;
    /// Score and maximum per stage, 1 to kLastStage (index 0: the whole pipeline's checks).
    std::vector<std::pair<double, double>> stage_scores() const;
    /// The stages that have checks, in kStageReportOrder, each with its score and its checks
    /// passed.
    std::vector<StageTally> stage_tallies() const;
};

}  // namespace raystep::grade
