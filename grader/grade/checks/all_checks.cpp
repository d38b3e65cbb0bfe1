#include "grader/grade/checks/stage_checks.h"

namespace raystep::grade {

std::vector<CheckDefinition> all_checks() {
    std::vector<CheckDefinition> checks;
    for (auto stage : {stage1_checks, stage2_checks, stage3_checks, stage4_checks, stage5_checks,
                       stage6_checks, stage7_checks, stage8_checks, stage9_checks, stage10_checks,
                       stage11_checks, render_checks}) {
        for (CheckDefinition& check : stage())
            checks.push_back(std::move(check));
    }
    return checks;
}

}  // namespace raystep::grade
