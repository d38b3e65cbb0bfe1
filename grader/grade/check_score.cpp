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
    result.max_score = entry.points;
    result.visibility = entry.visibility;
    // A stage that did not compile or is still a stub earns nothing, nor does a check that could
    // not measure anything; one that crashed or ran out of time partway keeps the cases it
    // answered right.
    const bool scorable = !measure.grader_error && measure.outcome != Outcome::did_not_compile &&
                          measure.outcome != Outcome::not_implemented;
    result.score = scorable ? entry.score(measure.fraction) : 0.0;
    // Passed means full points, in every report: the rubric may give full points short of every
    // case (a lecture method loses a few slivers by design), and Gradescope shows a test's status
    // in colour, so a check at its maximum must not read "failed", nor one short of it "passed"
    // (a speed check's partial points). A stub, a check that did not compile or could not measure
    // anything keeps its own outcome: it earned nothing. A check worth no points (reported only)
    // keeps what it measured.
    result.outcome = measure.outcome;
    if (scorable && entry.points > 0.0) {
        if (result.score >= entry.points) {
            result.outcome = Outcome::passed;
        } else if (measure.outcome == Outcome::passed) {
            result.outcome = Outcome::failed;
        }
    }
    result.summary = measure.summary;
    result.counterexamples = measure.counterexamples;
    result.metrics = measure.metrics;
    result.images = measure.images;
    result.details = measure.details;
    return result;
}

}  // namespace raystep::grade
