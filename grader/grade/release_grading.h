#pragma once

#include <cstddef>
#include <filesystem>

namespace raystep::grade {

/// Writes a student release's grading/ folder: `folder`/public/CHECK.json for every public check
/// (public_checks(source), grader/grade/checks/data_judged.h), decided now by the grader's oracles
/// and the reference's renders of the scenes under `source`, and
/// `folder`/rubric.json, a copy of `rubric`, which scores them; and `folder`/stage3-reference.json,
/// the reference's count of stage 3's public cases right per function (case_file_judges.h).
/// `raystep grade` runs them on the student's build (app/cli/grade_command.cpp). Returns the
/// number of case files written.
std::size_t write_release_grading(const std::filesystem::path& source,
                                  const std::filesystem::path& rubric,
                                  const std::filesystem::path& folder);

}  // namespace raystep::grade
