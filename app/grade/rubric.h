#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "app/report/grade_report.h"

namespace raystep::grade {

/// How one check is scored (grader/rubric/rubric.json; docs/instructor.md, "4. The rubric"). Every
/// check measures a fraction in [0, 1]: of cases passed, of pixels that match, or the speed ratio
/// to the reference. The score is `points` at or above `full_at`, 0 at or below `zero_at`, and in
/// proportion between, so that a nearly right stage keeps most of its points and a broken one
/// none.
struct RubricEntry {
    double points = 0.0;
    double full_at = 1.0;
    double zero_at = 0.0;
    Visibility visibility = Visibility::visible;

    double score(double fraction) const;
};

struct Rubric {
    std::map<std::string, RubricEntry> checks;  ///< by check id

    /// Throws std::out_of_range naming the check when the rubric has no entry for it.
    const RubricEntry& entry(const std::string& id) const;
};

/// A check's result as the rubric scores what it measured, the same in the grader
/// (grader/grade/check_score.h) and in `raystep grade` (public_check_run.h): the check's names,
/// its points and visibility from `entry`, its score and outcome from the `measured` outcome and
/// `fraction`. A stage that did not compile or is still a stub earns nothing, nor does a check
/// that could not measure anything (`scorable` false); one that crashed or ran out of time
/// partway keeps the cases it answered right. The caller fills in the rest (summary,
/// counterexamples, metrics).
CheckResult scored_check(std::string id, int stage, std::string kind, std::string name,
                         const RubricEntry& entry, Outcome measured, double fraction,
                         bool scorable = true);

/// Reads a rubric file. Throws std::runtime_error naming the file and the problem (a missing
/// field, a zero_at not below full_at, an unknown visibility).
Rubric load_rubric(const std::filesystem::path& file);

}  // namespace raystep::grade
