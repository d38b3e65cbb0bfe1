#include "grader/grade/check_score.h"

namespace raystep::grade {

CheckResult score_check(const CheckDefinition& check, const CheckMeasure& measure,
                        const Rubric& rubric) {
    CheckResult result =
        scored_check(check.id, check.stage, check.kind, check.name, rubric.entry(check.id),
                     measure.outcome, measure.fraction, !measure.grader_error);
    result.summary = measure.summary;
    result.counterexamples = measure.counterexamples;
    result.metrics = measure.metrics;
    result.images = measure.images;
    result.details = measure.details;
    return result;
}

}  // namespace raystep::grade
