#pragma once

#include <vector>

#include "app/check/case_scoring.h"
#include "app/check/stage3_methods.h"

namespace raystep {

/// `method` run on every case of `cases` in this process, and scored as the grader scores a
/// probe's answers: the grader's tests of stage 3's families and tolerances against known right
/// and wrong methods.
inline MethodScore score_in_process(const Stage3Method& method, const CaseFamily& cases) {
    std::vector<CaseAnswer> answers;
    for (const RayCase& ray_case : cases.cases)
        answers.push_back(run_method(method, ray_case));
    return score_family(method, cases, answers);
}

}  // namespace raystep
