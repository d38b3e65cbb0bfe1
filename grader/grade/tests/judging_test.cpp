// The checks' shared building blocks (grader/grade/checks/judging.h) on cases and answers made by
// hand: judge_result's three outcomes, the seeding that lets `--case i` rebuild one generated
// case alone, and the ids and kinds of a stage's three case checks.

#include <string>
#include <vector>

#include "app/probe/tests/probe_answers.h"
#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "grader/grade/checks/judging.h"

using namespace raystep;
using namespace raystep::grade;
using raystep::testing::result_answer;

namespace {

Judgement judge_positive(const ProbeAnswer& answer) {
    return judge_result(
        answer, "a positive number", [](const probe::Json& value) { return value.get<double>(); },
        [](double got) { return got > 0; }, [](double got) { return full_text(got); });
}

// A case whose input is the first number its generator draws.
ProbeCase drawn_case(PortableRandom& random, int) {
    return {full_text(random.unit()), {}, {}, ""};
}

}  // namespace

TEST_CASE("judge_result: an accepted result is right, a rejected one wrong as describe writes it",
          "[grader]") {
    CHECK(judge_positive(result_answer(2.5)).passed);
    const Judgement rejected = judge_positive(result_answer(-1.5));
    CHECK_FALSE(rejected.passed);
    CHECK(rejected.expected == "a positive number");
    CHECK(rejected.got == "-1.5");
}

TEST_CASE("judge_result: no result is wrong with nothing got", "[grader]") {
    ProbeAnswer threw;
    threw.kind = ProbeAnswer::Kind::threw;
    const Judgement j = judge_positive(threw);
    CHECK_FALSE(j.passed);
    CHECK(j.expected == "a positive number");
    CHECK(j.got.empty());
}

TEST_CASE("add_seeded_cases: the case at index i is drawn from PortableRandom(seed, i)",
          "[grader]") {
    std::vector<ProbeCase> cases(2);
    add_seeded_cases(cases, 42, 3, drawn_case);
    REQUIRE(cases.size() == 5);
    for (std::size_t i = 2; i < cases.size(); ++i) {
        CAPTURE(i);
        PortableRandom random(42, i);
        CHECK(cases[i].input == full_text(random.unit()));
    }
}

TEST_CASE("add_seeded_case_groups: a group is drawn from its first case's generator", "[grader]") {
    std::vector<ProbeCase> cases(1);
    add_seeded_case_groups(cases, 7, 2, [](PortableRandom& random, int k) {
        return std::vector<ProbeCase>(2, drawn_case(random, k));
    });
    REQUIRE(cases.size() == 5);
    PortableRandom first(7, 1);
    PortableRandom second(7, 3);
    CHECK(cases[1].input == full_text(first.unit()));
    CHECK(cases[3].input == full_text(second.unit()));
}

TEST_CASE("stage_case_checks: stageN.unit, stageN.hidden and stageN.oracle, in that order",
          "[grader]") {
    const auto none = [] { return std::vector<ProbeCase>(); };
    const std::vector<CheckDefinition> checks =
        stage_case_checks({6, "public", none, "hidden", none, "oracle", none});
    REQUIRE(checks.size() == 3);
    CHECK(checks[0].id == "stage6.unit");
    CHECK(checks[0].kind == "unit");
    CHECK(checks[0].name == "public");
    CHECK(checks[1].id == "stage6.hidden");
    CHECK(checks[1].kind == "unit");
    CHECK(checks[2].id == "stage6.oracle");
    CHECK(checks[2].kind == "oracle");
    for (const CheckDefinition& check : checks)
        CHECK(check.stage == 6);
}
