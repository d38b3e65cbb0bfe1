// FunctionShare on answers made by hand: a contract check scores the share of functions that keep
// its sentence on every case they were asked, not the share of cases.

#include <string>
#include <vector>

#include "app/probe/tests/probe_answers.h"
#include "base/testing/catch.h"
#include "grader/grade/tests/hand_made_cases.h"
#include "grading/3_intersect/function_share.h"

using namespace raystep::grade;
using raystep::grade::hand_made::session;
using raystep::grade::hand_made::wants_one;
using raystep::testing::result_answer;

namespace {

// Cases of three functions: four of "plane", one of "sphere", one of "closest_hit", in order.
std::vector<ProbeCase> three_functions(FunctionShare& share) {
    std::vector<ProbeCase> cases;
    for (int k = 0; k < 4; ++k)
        cases.push_back(share.counted(wants_one("plane case"), "plane"));
    cases.push_back(share.counted(wants_one("sphere case"), "sphere"));
    cases.push_back(share.counted(wants_one("closest case"), "closest_hit"));
    return cases;
}

std::vector<ProbeAnswer> all_right(std::size_t count) {
    return std::vector<ProbeAnswer>(count, result_answer(1));
}

}  // namespace

TEST_CASE("function share: every function right keeps the whole fraction", "[grader]") {
    FunctionShare share;
    const std::vector<ProbeCase> cases = three_functions(share);
    CheckMeasure m =
        judge_answers({}, "stage3.contract.x", cases, {0, 1, 2, 3, 4, 5}, session(all_right(6)));
    share.score(m);
    CHECK(m.fraction == 1.0);
    CHECK(m.outcome == Outcome::passed);
    CHECK(m.metrics.at("functions") == 3.0);
    CHECK(m.summary == "6 of 6 cases right; every function asked keeps it");
}

TEST_CASE("function share: one wrong case of a function with one case costs its third, not a sixth",
          "[grader]") {
    FunctionShare share;
    const std::vector<ProbeCase> cases = three_functions(share);
    std::vector<ProbeAnswer> answers = all_right(6);
    answers[4] = result_answer(2);  // the sphere's only case
    CheckMeasure m =
        judge_answers({}, "stage3.contract.x", cases, {0, 1, 2, 3, 4, 5}, session(answers));
    share.score(m);
    CHECK(m.fraction == 2.0 / 3.0);
    CHECK(m.outcome == Outcome::failed);
    CHECK(m.summary == "5 of 6 cases right; broken in sphere (2 of 3 functions keep it)");
}

TEST_CASE("function share: a function right on three cases and wrong on one is broken",
          "[grader]") {
    FunctionShare share;
    const std::vector<ProbeCase> cases = three_functions(share);
    std::vector<ProbeAnswer> answers = all_right(6);
    answers[2] = result_answer(0);
    CheckMeasure m =
        judge_answers({}, "stage3.contract.x", cases, {0, 1, 2, 3, 4, 5}, session(answers));
    share.score(m);
    CHECK(m.fraction == 2.0 / 3.0);
    CHECK(m.metrics.at("functions keeping it") == 2.0);
}

TEST_CASE("function share: a stub's case and an unanswered case each break their function",
          "[grader]") {
    FunctionShare share;
    const std::vector<ProbeCase> cases = three_functions(share);
    std::vector<ProbeAnswer> answers = all_right(6);
    answers[0].kind = ProbeAnswer::Kind::not_implemented;
    answers[0].message = "stage 3: intersect_plane is not implemented yet, see docs/stage3.md";
    answers[5] = ProbeAnswer{};  // unanswered: the probe stopped
    CheckMeasure m =
        judge_answers({}, "stage3.contract.x", cases, {0, 1, 2, 3, 4, 5}, session(answers));
    share.score(m);
    CHECK(m.fraction == 1.0 / 3.0);
}

TEST_CASE("function share: only the functions of the cases asked count (--case N)", "[grader]") {
    FunctionShare share;
    const std::vector<ProbeCase> cases = three_functions(share);
    CheckMeasure m =
        judge_answers({}, "stage3.contract.x", cases, {4}, session({result_answer(1)}));
    share.score(m);
    CHECK(m.fraction == 1.0);
    CHECK(m.metrics.at("functions") == 1.0);
}
