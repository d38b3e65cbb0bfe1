// score_check: points by the rubric, and "passed" exactly when a check worth points earns all
// of them, whatever it measured.

#include "grader/grade/check_score.h"

#include "base/testing/catch.h"

using namespace raystep::grade;

namespace {

CheckDefinition oracle_check(const std::string& id) {
    return {id, 3, "oracle", "a check", {}};
}

Rubric rubric(double points, double full_at, double zero_at) {
    Rubric made;
    made.checks["stage3.oracle.x"] = {points, full_at, zero_at, Visibility::visible};
    return made;
}

CheckMeasure measured(Outcome outcome, double fraction) {
    CheckMeasure made;
    made.outcome = outcome;
    made.fraction = fraction;
    return made;
}

}  // namespace

TEST_CASE("score_check: full points short of every case is passed", "[grader]") {
    // The lecture's projection method loses a few slivers by design; the rubric allows for it.
    const CheckResult r = score_check(oracle_check("stage3.oracle.x"),
                                      measured(Outcome::failed, 0.98), rubric(3, 0.97, 0.7));
    CHECK(r.score == 3.0);
    CHECK(r.outcome == Outcome::passed);
}

TEST_CASE("score_check: a passed measure short of full points is failed", "[grader]") {
    // A speed check that answered right but ran slowly.
    const CheckResult r = score_check(oracle_check("stage3.oracle.x"),
                                      measured(Outcome::passed, 0.06), rubric(2, 0.1, 0.02));
    CHECK(r.score == Approx(1.0));
    CHECK(r.outcome == Outcome::failed);
}

TEST_CASE("score_check: a crash that still earned full points is passed", "[grader]") {
    const CheckResult r = score_check(oracle_check("stage3.oracle.x"),
                                      measured(Outcome::crashed, 0.995), rubric(3, 0.99, 0.7));
    CHECK(r.score == 3.0);
    CHECK(r.outcome == Outcome::passed);
}

TEST_CASE(
    "score_check: a stub or a stage that did not compile earns nothing and keeps its "
    "outcome",
    "[grader]") {
    for (const Outcome outcome : {Outcome::not_implemented, Outcome::did_not_compile}) {
        const CheckResult r = score_check(oracle_check("stage3.oracle.x"), measured(outcome, 1.0),
                                          rubric(3, 1.0, 0.5));
        CHECK(r.score == 0.0);
        CHECK(r.outcome == outcome);
    }
}

TEST_CASE("score_check: a grader error earns nothing, even where the rubric pays for 0",
          "[grader]") {
    CheckMeasure m = measured(Outcome::failed, 0.0);
    m.grader_error = true;
    const CheckResult r = score_check(oracle_check("stage3.oracle.x"), m, rubric(3, 1.0, -1.0));
    CHECK(r.score == 0.0);
    CHECK(r.outcome == Outcome::failed);
}

TEST_CASE("score_check: a check worth no points keeps what it measured", "[grader]") {
    const CheckResult passed = score_check(oracle_check("stage3.oracle.x"),
                                           measured(Outcome::passed, 1.0), rubric(0, 1.0, 0.5));
    CHECK(passed.outcome == Outcome::passed);
    const CheckResult failed = score_check(oracle_check("stage3.oracle.x"),
                                           measured(Outcome::failed, 0.0), rubric(0, 1.0, 0.5));
    CHECK(failed.outcome == Outcome::failed);
}
