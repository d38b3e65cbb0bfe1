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

/// Reads a rubric file. Throws std::runtime_error naming the file and the problem (a missing
/// field, a zero_at not below full_at, an unknown visibility).
Rubric load_rubric(const std::filesystem::path& file);

}  // namespace raystep::grade
