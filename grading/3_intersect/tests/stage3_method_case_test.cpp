// Stage 3's cases as the grader asks them: one query per case, a stub's answer inside the result
// counted as not implemented, and a student's reproduce line that is the case itself.

#include <algorithm>
#include <string>
#include <vector>

#include "app/check/case_file.h"
#include "app/protocol/probe_json.h"
#include "base/testing/catch.h"
#include "grader/grade/checks/stage_checks.h"

using namespace raystep;
using namespace raystep::grade;

namespace {

const char* const kCaseFile = R"(family contract seed 0
case 11
ray 0 0 -5 0 0 1 0 inf
sphere 0 0 0 1 hit 4 tolerance 1e-12 normal 0 0 -1 tolerance 1e-12
end
)";

Stage3Method method_named(const std::string& name) {
    const std::vector<Stage3Method> methods = stage3_methods();
    return *std::find_if(methods.begin(), methods.end(),
                         [&](const Stage3Method& m) { return m.name == name; });
}

// The probe's result for one case: a list of one case answer.
ProbeAnswer answered(const CaseAnswer& answer) {
    ProbeAnswer made;
    made.kind = ProbeAnswer::Kind::result;
    made.value = probe::Json::array({probe::case_answer(answer)});
    return made;
}

CaseAnswer sphere_hit(double t) {
    CaseAnswer answer;
    answer.hits = {Hit{t, {0, 0, -1}}};
    return answer;
}

}  // namespace

TEST_CASE("method_case: the case is asked alone and judged as raystep check judges it",
          "[grader]") {
    const CaseFamily family = parse_case_file(kCaseFile, "contract.cases").front();
    std::size_t leaks = 0;
    const ProbeCase c =
        method_case(method_named("intersect_sphere"), family, family.cases.front(), leaks);
    CHECK(c.query.call == "stage3_cases");
    CHECK(c.query.args.at("method") == "intersect_sphere");
    CHECK(c.query.args.at("cases").size() == 1);

    CHECK(c.judge(answered(sphere_hit(4))).passed);
    const Judgement miss = c.judge(answered(CaseAnswer{{std::nullopt}, {}, {}, false, ""}));
    CHECK_FALSE(miss.passed);
    CHECK(miss.got.find("false miss") == 0);
}

TEST_CASE(
    "method_case: a stub's answer inside the result makes a not-implemented check, not a "
    "pass of no cases",
    "[grader]") {
    const CaseFamily family = parse_case_file(kCaseFile, "contract.cases").front();
    std::size_t leaks = 0;
    CaseAnswer stubbed;
    stubbed.not_implemented = true;
    stubbed.error = "stage 3: intersect_sphere is not implemented yet, see docs/stage3.md";
    const std::vector<ProbeCase> cases = {
        method_case(method_named("intersect_sphere"), family, family.cases.front(), leaks)};
    ProbeSession session;
    session.answers = {answered(stubbed)};
    const CheckMeasure m = judge_answers({}, "stage3.oracle.intersect_sphere", cases, {0}, session);
    CHECK(m.outcome == Outcome::not_implemented);
    CHECK(m.fraction == 0.0);
    CHECK(m.metrics.at("cases") == 1.0);
    CHECK(m.summary == stubbed.error);
}

TEST_CASE("method_case: the student's reproduce line writes the case to a file and checks it",
          "[grader]") {
    const CaseFamily family = parse_case_file(kCaseFile, "contract.cases").front();
    std::size_t leaks = 0;
    const ProbeCase c =
        method_case(method_named("intersect_sphere"), family, family.cases.front(), leaks);
    const std::string& line = c.student_reproduce;
    CHECK(line.find("raystep-grade") == std::string::npos);
    const std::string start = "cat > contract-11.cases <<'EOF'\n";
    REQUIRE(line.rfind(start, 0) == 0);
    const std::size_t end = line.find("EOF\n", start.size());
    REQUIRE(end != std::string::npos);
    // The file holds exactly the case, as the case-file reader reads it back.
    const std::vector<CaseFamily> written =
        parse_case_file(line.substr(start.size(), end - start.size()), "contract-11.cases");
    REQUIRE(written.size() == 1);
    REQUIRE(written.front().cases.size() == 1);
    CHECK(written.front().name == "contract");
    CHECK(case_text(written.front().cases.front()) == case_text(family.cases.front()));
    CHECK(line.substr(end + 4) ==
          "build/student/bin/raystep check --stage 3 contract-11.cases --method intersect_sphere "
          "--case 11");
}
