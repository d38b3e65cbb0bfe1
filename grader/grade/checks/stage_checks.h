#pragma once

#include <vector>

#include "grader/grade/check_definition.h"

namespace raystep::grade {

// The checks of each stage, in grader/grade/checks/. all_checks() puts them together.

std::vector<CheckDefinition> stage1_checks();
std::vector<CheckDefinition> stage2_checks();
std::vector<CheckDefinition> stage3_checks();
std::vector<CheckDefinition> stage4_checks();
std::vector<CheckDefinition> stage5_checks();
std::vector<CheckDefinition> stage6_checks();
std::vector<CheckDefinition> stage7_checks();
std::vector<CheckDefinition> render_checks();

}  // namespace raystep::grade
