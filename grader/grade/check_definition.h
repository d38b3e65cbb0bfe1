#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/report/grade_report.h"
#include "grader/grade/probe_builder.h"
#include "grader/grade/probe_client.h"

namespace raystep::grade {

/// What grading needs beyond the probes: where images go, the reference probe (speed checks time
/// it beside the submission's), and how a reproduce command starts.
struct GradingContext {
    const ProbeSet* probes = nullptr;
    std::filesystem::path source;           ///< scenes/ for render checks: the work copy
    std::filesystem::path grader_source;    ///< the grader's own tree: stage 3's public cases
    std::filesystem::path report_folder;    ///< render checks write their images here
    std::filesystem::path reference_probe;  ///< raystep-probe-reference
    std::string reproduce;                  ///< "raystep-grade submission PATH", to which
                                            ///< " --check ID --case N" is appended
    std::optional<std::size_t> only_case;   ///< --case N: ask the probe that case alone
    /// Where the reference's noisy renders are kept for other grades from the same eyes
    /// (checks/kept_renders.h): cache/renders/eye-SEED when the eye seed was given (a batch's, or
    /// --eye-seed) and a --cache too; empty otherwise, since no other grade would look from a
    /// seed drawn for this one.
    std::filesystem::path kept_renders;
    /// The seed of the timed runs' jitter (stage 4's walks and speed checks), drawn anew for
    /// every grade: the digest a timed run answers is then one no submission can know before it
    /// walks, so a run's time is the time of its walk, not of a digest written in beforehand.
    std::uint64_t timed_walk_seed = 0;
    /// The seed of the eyes the render checks look from (checks/moved_eye.h): drawn anew for
    /// every grade unless given (`--eye-seed`), which a render check's reproduce lines name.
    std::uint64_t eye_seed = 0;
};

/// A seed drawn anew for a grade (GradingContext::timed_walk_seed, eye_seed), from the system's
/// source of random numbers.
std::uint64_t fresh_grade_seed();

/// What a check found, before the rubric turns it into points: `fraction` in [0, 1] is what the
/// rubric scores (cases passed, pixels matching, speed against the reference).
struct CheckMeasure {
    Outcome outcome = Outcome::failed;
    double fraction = 0.0;
    /// The check could not measure anything (it asked no cases): the grader's mistake, never the
    /// submission's merit, so it earns nothing whatever the rubric says, and the summary says so.
    bool grader_error = false;
    std::string summary;
    std::vector<Counterexample> counterexamples;
    std::map<std::string, double> metrics;
    RenderImages images;
    std::string details;
};

struct CheckDefinition {
    std::string id;    ///< "stage1.unit"; the rubric's key
    int stage = 0;     ///< whose probe answers it: 1 to 9, or 0 for the whole pipeline
    std::string kind;  ///< "unit", "oracle", "render", "speed"
    std::string name;
    std::function<CheckMeasure(const GradingContext&, const BuiltProbe&)> measure;
    /// The check whose measurement this one shares and would wait for (stage 4's timed walks);
    /// empty for none. The grader runs such a check after all others, so that it finds the
    /// measurement made instead of holding a worker idle while it is made.
    std::string measured_by = {};
};

/// Every check, stage by stage (grader/grade/checks/).
std::vector<CheckDefinition> all_checks();

/// The order a grade starts `checks` in, as indices: every check that measures for itself, then
/// every check measured_by another, each in the order given; the speed checks, which run alone
/// afterwards, are not in it.
std::vector<std::size_t> check_start_order(const std::vector<CheckDefinition>& checks);

// Building blocks for checks that send cases to a probe and judge each answer.

/// How one answer compares with the grader's expectation: passed, or what was expected and got.
struct Judgement {
    bool passed = false;
    std::string expected;
    std::string got;
    /// The function under check is still a stub: the NotImplemented message it threw, when the
    /// probe carried it inside a result (stage 3's cases answer each case on its own) rather than
    /// as the whole answer. Empty otherwise.
    std::string not_implemented;
};

inline Judgement right() {
    return {true, "", "", ""};
}
inline Judgement wrong(std::string expected, std::string got) {
    return {false, std::move(expected), std::move(got), ""};
}
/// The case met a stub: wrong, and counted as not implemented.
inline Judgement stub(std::string message) {
    return {false, "", "", std::move(message)};
}

/// One case of a check: what the probe is asked, and how its answer is judged. The judge sees
/// only the probe's answer; the expectation lives in the grader, in the judge.
struct ProbeCase {
    std::string input;  ///< the case, readable, for the report
    ProbeQuery query;
    std::function<Judgement(const ProbeAnswer&)> judge;
    /// What a student can run in the student release to see this case again: the call written
    /// out as C++ for a Catch2 test, a `raystep check` or `raystep trace` command. Empty when
    /// there is none.
    std::string student_reproduce;
};

/// Asks the probe every case in one run (only context.only_case, when set) and judges the
/// answers (judge_answers).
CheckMeasure run_cases(const GradingContext& context, const std::string& check_id,
                       const BuiltProbe& probe, const std::vector<ProbeCase>& cases,
                       const ProbeRunLimits& limits = {});

/// Cases answered together: one query whose result is a list with one element per case (a
/// structure built once over a scene, asked about every ray). Each case's judge sees its element
/// as the result. Reproducing one case (--case N) asks `one_case` for it alone, a query whose
/// result is a list of one; the cases' own `query` is left empty, so that a batch holds its
/// inputs (a scene of hundreds of primitives) once, not once per case.
struct CaseBatch {
    ProbeQuery query;
    std::function<ProbeQuery(std::size_t element)> one_case;
    std::vector<ProbeCase> cases;
};

/// run_cases for batches: the cases are numbered across the batches, in order, and each is
/// judged, counted and reproduced on its own.
CheckMeasure run_batched_cases(const GradingContext& context, const std::string& check_id,
                               const BuiltProbe& probe, const std::vector<CaseBatch>& batches,
                               const ProbeRunLimits& limits = {});

/// Judges a probe's answers to the cases at `asked` (indices into `cases`, in the order they were
/// asked; session.answers follows the same order). Every case asked is in the denominator,
/// answered or not: `fraction` is the share passed, and a stub's case, an unanswered one or an
/// unreadable one counts as wrong. The outcome: a grader error (failed, nothing earned) when no
/// case was asked; timed_out or crashed when the run ended before answering everything (the
/// sandbox's account in details); not_implemented when every case met a stub; passed when every
/// case passed; else failed. The summary names the functions that are stubs. Keeps the first few
/// counterexamples, wrong answers before stubs.
CheckMeasure judge_answers(const GradingContext& context, const std::string& check_id,
                           const std::vector<ProbeCase>& cases,
                           const std::vector<std::size_t>& asked, const ProbeSession& session);

/// The function a stub's NotImplemented message names ("stage 3: intersect_sphere is not
/// implemented yet, ..." gives "intersect_sphere"); the whole message, clipped, when it does not
/// read that way (student code may throw anything).
std::string stub_function(const std::string& message);

/// The answer's text for a report: the result's JSON, or what was thrown, or why there is none.
std::string answer_text(const ProbeAnswer& answer);

/// What a check measures of a probe that was not built: did not compile, with the compiler's
/// first lines (or the missing files) as the details.
CheckMeasure not_compiled(const BuiltProbe& probe);

}  // namespace raystep::grade
