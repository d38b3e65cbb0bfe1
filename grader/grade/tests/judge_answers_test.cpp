// run_cases' judging (judge_answers) on answers made by hand: every case asked is in the
// denominator, a stub's case is never a pass, and the summary says which functions are stubs.

#include <stdexcept>
#include <string>
#include <vector>

#include "app/probe/tests/probe_answers.h"
#include "base/testing/catch.h"
#include "grader/grade/check_definition.h"
#include "grader/grade/tests/hand_made_cases.h"

using namespace raystep::grade;
using raystep::grade::hand_made::session;
using raystep::grade::hand_made::wants_one;
using raystep::testing::result_answer;

namespace {

ProbeAnswer stub_answer(const std::string& function) {
    ProbeAnswer answer;
    answer.kind = ProbeAnswer::Kind::not_implemented;
    answer.message = "stage 1: " + function + " is not implemented yet, see docs/stage1.md";
    return answer;
}

std::vector<ProbeCase> cases(std::size_t count) {
    std::vector<ProbeCase> made;
    for (std::size_t k = 0; k < count; ++k)
        made.push_back(wants_one("case " + std::to_string(k)));
    return made;
}

std::vector<std::size_t> every(std::size_t count) {
    std::vector<std::size_t> asked;
    for (std::size_t k = 0; k < count; ++k)
        asked.push_back(k);
    return asked;
}

GradingContext context() {
    GradingContext made;
    made.reproduce = "raystep-grade submission alice.zip";
    return made;
}

}  // namespace

TEST_CASE("judge_answers: every case right passes with the whole fraction", "[grader]") {
    const CheckMeasure m =
        judge_answers(context(), "stage1.unit", cases(3), every(3),
                      session({result_answer(1), result_answer(1), result_answer(1)}));
    CHECK(m.outcome == Outcome::passed);
    CHECK(m.fraction == 1.0);
    CHECK(m.summary == "3 of 3 cases right");
    CHECK(m.counterexamples.empty());
}

TEST_CASE("judge_answers: a stub's cases count as wrong, and the summary names the function",
          "[grader]") {
    const CheckMeasure m = judge_answers(
        context(), "stage1.unit", cases(4), every(4),
        session({stub_answer("cross"), result_answer(1), result_answer(2), stub_answer("cross")}));
    CHECK(m.outcome == Outcome::failed);
    CHECK(m.fraction == 0.25);
    CHECK(m.metrics.at("cases") == 4.0);
    CHECK(m.summary == "1 of 4 cases right; not implemented: cross");
    // The wrong answer first, then the stubs; each with its own case number.
    REQUIRE(m.counterexamples.size() == 3);
    CHECK(m.counterexamples[0].got == "2.0");
    CHECK(m.counterexamples[0].reproduce ==
          "raystep-grade submission alice.zip --check stage1.unit --case 2");
    CHECK(m.counterexamples[0].student_reproduce == "case 2({1, 0, 0}, {1, 0, 0})");
    CHECK(m.counterexamples[1].reproduce.substr(m.counterexamples[1].reproduce.size() - 8) ==
          "--case 0");
    CHECK(m.counterexamples[2].reproduce.substr(m.counterexamples[2].reproduce.size() - 8) ==
          "--case 3");
    CHECK(m.counterexamples[1].got.find("not implemented: stage 1: cross") == 0);
}

TEST_CASE("judge_answers: a judge that reports a stub inside a result is never a pass",
          "[grader]") {
    // Stage 3's answers carry a stub per case inside the result; the judge says so.
    std::vector<ProbeCase> made = cases(2);
    made[1].judge = [](const ProbeAnswer&) {
        Judgement j = stub("stage 3: intersect_sphere is not implemented yet, see docs/stage3.md");
        j.passed = true;  // a careless judge: the stub still wins
        return j;
    };
    const CheckMeasure m = judge_answers(context(), "stage3.hidden", made, every(2),
                                         session({result_answer(1), result_answer(1)}));
    CHECK(m.outcome == Outcome::failed);
    CHECK(m.fraction == 0.5);
    CHECK(m.summary == "1 of 2 cases right; not implemented: intersect_sphere");
}

TEST_CASE("judge_answers: every case a stub is not implemented, naming every stub", "[grader]") {
    SECTION("one function: its own message, which names the handout") {
        const CheckMeasure m = judge_answers(context(), "stage1.unit", cases(2), every(2),
                                             session({stub_answer("dot"), stub_answer("dot")}));
        CHECK(m.outcome == Outcome::not_implemented);
        CHECK(m.fraction == 0.0);
        CHECK(m.summary == "stage 1: dot is not implemented yet, see docs/stage1.md");
    }
    SECTION("several functions: their names, in the order met") {
        const CheckMeasure m =
            judge_answers(context(), "stage1.unit", cases(3), every(3),
                          session({stub_answer("dot"), stub_answer("cross"), stub_answer("dot")}));
        CHECK(m.outcome == Outcome::not_implemented);
        CHECK(m.summary == "not implemented: dot, cross");
    }
}

TEST_CASE("judge_answers: a check that asked nothing is a grader error, never a pass", "[grader]") {
    const CheckMeasure m = judge_answers(context(), "stage1.unit", {}, {}, session({}));
    CHECK(m.grader_error);
    CHECK(m.outcome == Outcome::failed);
    CHECK(m.fraction == 0.0);
    CHECK(m.summary == "grader error: the check asked no cases");
}

TEST_CASE("judge_answers: unanswered cases stay in the denominator", "[grader]") {
    ProbeSession ended = session({result_answer(1), ProbeAnswer{}, ProbeAnswer{}, ProbeAnswer{}});
    SECTION("a crash") {
        ended.run.signal = 11;
        const CheckMeasure m = judge_answers(context(), "stage1.unit", cases(4), every(4), ended);
        CHECK(m.outcome == Outcome::crashed);
        CHECK(m.fraction == 0.25);
        CHECK(m.summary.find("1 of 4 cases right; the probe answered 1 of 4 queries, then died "
                             "of signal 11") == 0);
    }
    SECTION("a timeout") {
        ended.run.timed_out = true;
        const CheckMeasure m = judge_answers(context(), "stage1.unit", cases(4), every(4), ended);
        CHECK(m.outcome == Outcome::timed_out);
        CHECK(m.fraction == 0.25);
    }
}

TEST_CASE("judge_answers: a judge that cannot read an answer fails that case", "[grader]") {
    std::vector<ProbeCase> made = cases(2);
    made[0].judge = [](const ProbeAnswer&) -> Judgement {
        throw std::invalid_argument("not a vector");
    };
    const CheckMeasure m = judge_answers(context(), "stage1.unit", made, every(2),
                                         session({result_answer(1), result_answer(1)}));
    CHECK(m.outcome == Outcome::failed);
    CHECK(m.fraction == 0.5);
    REQUIRE(m.counterexamples.size() == 1);
    CHECK(m.counterexamples[0].got == "unreadable: not a vector");
}

TEST_CASE("judge_answers: only the cases asked are judged and counted", "[grader]") {
    // --case 2: the probe was asked case 2 alone.
    const CheckMeasure m =
        judge_answers(context(), "stage1.unit", cases(5), {2}, session({result_answer(0)}));
    CHECK(m.metrics.at("cases") == 1.0);
    REQUIRE(m.counterexamples.size() == 1);
    CHECK(m.counterexamples[0].input == "case 2");
}

TEST_CASE("stub_function: the function a stub's message names", "[grader]") {
    CHECK(stub_function("stage 4: Bvh::Bvh is not implemented yet, see docs/stage4.md") ==
          "Bvh::Bvh");
    // Student code may throw NotImplemented with any text: then the text itself.
    CHECK(stub_function("nothing here") == "nothing here");
    CHECK(stub_function(": is not implemented") == ": is not implemented");
}
