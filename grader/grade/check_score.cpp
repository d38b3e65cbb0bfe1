#include "grader/grade/check_score.h"

namespace raystep::grade {

CheckResult score_check(const CheckDefinition& check, const CheckMeasure& measure,
                        const Rubric& rubric) {
    const RubricEntry& entry = rubric.entry(check.id);
    CheckResult result;
    result.id = check.id;
    result.stage = check.stage;
    result.kind = check.kind;
    result.name = check.name;
    result.outcome = measure.outcome;
    result.max_score = entry.points;
    result.visibility = entry.visibility;
    // A stage that did not compile or is still a stub earns nothing; one that crashed or ran out
    // of time partway keeps the cases it answered right.
    const bool scorable =
        measure.outcome != Outcome::did_not_compile && measure.outcome != Outcome::not_implemented;
    result.score = scorable ? entry.score(measure.fraction) : 0.0;
    result.summary = measure.summary;
    result.counterexamples = measure.counterexamples;
    result.metrics = measure.metrics;
    result.images = measure.images;
    result.details = measure.details;
    return result;
}

}  // namespace raystep::grade
