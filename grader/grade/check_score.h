#pragma once

#include "app/grade/rubric.h"
#include "app/report/grade_report.h"
#include "grader/grade/check_definition.h"

namespace raystep::grade {

/// The check's result as every report shows it: what it measured, scored by its rubric entry.
CheckResult score_check(const CheckDefinition& check, const CheckMeasure& measure,
                        const Rubric& rubric);

}  // namespace raystep::grade
