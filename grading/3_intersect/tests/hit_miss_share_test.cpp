// HitMissShare on answers made by hand: a function's check earns nothing unless it answers at
// least half the cases that must hit and half of those that must miss right, so that a function
// that answers one kind only earns nothing however many cases of that kind there are.

#include <vector>

#include "app/probe/tests/probe_answers.h"
#include "base/testing/catch.h"
#include "grader/grade/tests/hand_made_cases.h"
#include "grading/3_intersect/hit_miss_share.h"

using raystep::grade::CaseKind;
using raystep::grade::CheckMeasure;
using raystep::grade::HitMissShare;
using raystep::grade::judge_answers;
using raystep::grade::KindTally;
using raystep::grade::Outcome;
using raystep::grade::ProbeAnswer;
using raystep::grade::ProbeCase;
using raystep::grade::hand_made::session;
using raystep::grade::hand_made::wants_one;
using raystep::testing::result_answer;

namespace {

// One case that must hit, six that must miss and one near a boundary, in that order: most of the
// cases misses, as most of stage 3's are.
std::vector<ProbeCase> mostly_misses(HitMissShare& share) {
    std::vector<ProbeCase> cases;
    cases.push_back(share.counted(wants_one("a hit"), CaseKind::hit));
    for (int k = 0; k < 6; ++k)
        cases.push_back(share.counted(wants_one("a miss"), CaseKind::miss));
    cases.push_back(share.counted(wants_one("near an edge"), CaseKind::either));
    return cases;
}

CheckMeasure judged(HitMissShare& share, const std::vector<ProbeAnswer>& answers) {
    const std::vector<ProbeCase> cases = mostly_misses(share);
    CheckMeasure measure =
        judge_answers({}, "stage3.oracle.x", cases, {0, 1, 2, 3, 4, 5, 6, 7}, session(answers));
    share.score(measure);
    return measure;
}

}  // namespace

TEST_CASE("hit-miss share: a function that never hits earns nothing, though 7 of 8 cases are right",
          "[grader]") {
    HitMissShare share;
    std::vector<ProbeAnswer> answers(8, result_answer(1));
    answers[0] = result_answer(2);  // the one hit, missed
    const CheckMeasure m = judged(share, answers);
    CHECK(m.fraction == 0.0);
    CHECK(m.outcome == Outcome::failed);
    CHECK(m.summary.find("0 of the 1 cases that must hit right, 6 of the 6 that must miss") !=
          std::string::npos);
}

TEST_CASE("hit-miss share: fewer than half the misses right earns nothing", "[grader]") {
    HitMissShare share;
    std::vector<ProbeAnswer> answers(8, result_answer(1));
    for (const int k : {1, 2, 3, 4})
        answers[static_cast<std::size_t>(k)] = result_answer(2);
    CHECK(judged(share, answers).fraction == 0.0);
}

TEST_CASE("hit-miss share: half of each kind right keeps the share of all cases", "[grader]") {
    HitMissShare share;
    std::vector<ProbeAnswer> answers(8, result_answer(1));
    for (const int k : {1, 2, 3})
        answers[static_cast<std::size_t>(k)] = result_answer(2);
    const CheckMeasure m = judged(share, answers);
    CHECK(m.fraction == Approx(5.0 / 8.0));
    CHECK(m.summary == "5 of 8 cases right");
}

TEST_CASE("hit-miss share: every case right keeps the whole fraction and the summary as it was",
          "[grader]") {
    HitMissShare share;
    const CheckMeasure m = judged(share, std::vector<ProbeAnswer>(8, result_answer(1)));
    CHECK(m.fraction == 1.0);
    CHECK(m.outcome == Outcome::passed);
    CHECK(m.summary == "8 of 8 cases right");
}

TEST_CASE("kind tally: a kind not asked is kept; under half of one asked is not", "[grader]") {
    KindTally tally;
    tally.count(CaseKind::miss, true);
    tally.count(CaseKind::either, false);
    CHECK(tally.both_kinds_kept());
    tally.count(CaseKind::hit, false);
    CHECK_FALSE(tally.both_kinds_kept());
    CHECK(tally.shortfall() ==
          "earns nothing: 0 of the 1 cases that must hit right, 1 of the 1 that must miss, where "
          "at least half of each must be");
}
