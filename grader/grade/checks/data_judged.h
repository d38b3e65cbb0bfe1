#pragma once

#include <filesystem>
#include <vector>

#include "app/grade/public_case.h"
#include "grader/grade/check_definition.h"

namespace raystep::grade {

/// The case as the grader runs it: its query, and a judge built from its data judge
/// (app/grade/data_judge.h), the same one `raystep grade` builds from the release's case file.
ProbeCase data_judged_case(const PublicCase& c);

std::vector<ProbeCase> data_judged_cases(const std::vector<PublicCase>& cases);

/// Every public check whose cases the student release holds as data (grading/public/), decided
/// here, by the grader's oracles and the reference's renders of the scenes under `source`, when
/// the release is written.
std::vector<PublicCheck> public_checks(const std::filesystem::path& source);

}  // namespace raystep::grade
