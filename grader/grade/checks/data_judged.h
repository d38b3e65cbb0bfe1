#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "app/grade/public_case.h"
#include "grader/grade/check_definition.h"

namespace raystep::grade {

/// The case as the grader runs it: its query, and a judge built from its data judge
/// (app/grade/data_judge.h), the same one `raystep grade` builds from the release's case file.
ProbeCase data_judged_case(const PublicCase& c);

std::vector<ProbeCase> data_judged_cases(const std::vector<PublicCase>& cases);

/// What a stage's sample adds to each seed of its "stageN.oracle" check: far from every seed a
/// check draws from, so that no case of a sample is one of the grader's.
inline constexpr std::uint64_t kSampleSeedOffset = 0x5A3B'1E00'0000'0000;

/// The sample of stage `stage`'s generated cases, "stageN.sample".
PublicCheck sample_check(int stage, std::string name, std::vector<PublicCase> cases);

/// Every public check whose cases the student release holds as data (grading/public/), decided
/// here, by the grader's oracles and the reference's renders of the scenes under `source`, when
/// the release is written.
std::vector<PublicCheck> public_checks(const std::filesystem::path& source);

}  // namespace raystep::grade
