#pragma once

#include <filesystem>

#include "app/grade/public_case.h"
#include "app/grade/rubric.h"
#include "app/probe/call_table.h"
#include "app/report/grade_report.h"

namespace raystep::grade {

/// Runs a public check on this build, in process: each case's query answered by `calls`
/// (answer_in_process, call_reply.h), judged by its data judge, and scored by the rubric as the
/// grader scores it (scored_check, rubric.h: a fraction of cases right; a check whose every case
/// met a stub is not implemented and earns nothing). The first few counterexamples, wrong answers
/// before stubs, carry each case's input and its student reproduce line. A judge that measures a
/// share (a render's matching pixels) scores its check of one case by that share, as the grader
/// does. A relative "scene" argument names a file under `root` (the release's root). A sample
/// (kSampleKind) is worth nothing and needs no rubric entry; any other check throws
/// std::out_of_range when the rubric has none.
CheckResult run_public_check(const PublicCheck& check, const Rubric& rubric,
                             const probe::CallTable& calls, const std::filesystem::path& root);

}  // namespace raystep::grade
