// The public checks a student release holds as data (grading/public/): each written, read back
// and judged the same as the grader judges it, and each passed by the reference.

#include <filesystem>

#include <catch2/catch.hpp>

#include "app/grade/data_judge.h"
#include "app/grade/public_case.h"
#include "app/grade/rubric.h"
#include "app/probe/call_reply.h"
#include "grader/grade/checks/data_judged.h"

using namespace raystep;
using namespace raystep::grade;

namespace {

// Two verdicts alike: the same pass, the same words.
void require_alike(const Judgement& grader, const Verdict& release) {
    REQUIRE(grader.passed == release.passed);
    REQUIRE(grader.expected == release.expected);
    REQUIRE(grader.got == release.got);
    REQUIRE(grader.not_implemented == release.not_implemented);
}

}  // namespace

TEST_CASE("every public check the release writes reads back as written and is judged alike") {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / "raystep-public-checks-test";
    std::filesystem::remove_all(folder);
    const Rubric rubric = load_rubric(RAYSTEP_RUBRIC);
    const probe::CallTable reference = probe::stage_calls();
    ProbeAnswer stub;
    stub.kind = ProbeAnswer::Kind::threw;
    stub.exception_type = "other";
    stub.message = "an answer no judge takes";
    const std::vector<PublicCheck> checks = public_checks();
    REQUIRE_FALSE(checks.empty());
    for (const PublicCheck& written : checks) {
        INFO(written.id);
        REQUIRE(rubric.entry(written.id).points > 0);
        write_public_check(written, folder);
        const PublicCheck read = read_public_check(folder / (written.id + ".json"));
        REQUIRE(read.id == written.id);
        REQUIRE(read.stage == written.stage);
        REQUIRE(read.kind == written.kind);
        REQUIRE(read.name == written.name);
        REQUIRE(read.cases.size() == written.cases.size());
        REQUIRE_FALSE(read.cases.empty());
        for (std::size_t k = 0; k < read.cases.size(); ++k) {
            const PublicCase& w = written.cases[k];
            const PublicCase& r = read.cases[k];
            INFO("case " << k << ": " << w.input);
            REQUIRE(r.input == w.input);
            REQUIRE(r.query.call == w.query.call);
            REQUIRE(r.query.args == w.query.args);
            REQUIRE(r.judge == w.judge);
            REQUIRE(r.reproduce == w.reproduce);
            const ProbeCase graders = data_judged_case(w);
            const Judge releases = build_judge(r.judge);
            const ProbeAnswer answer = probe::answer_in_process(reference, r.query);
            require_alike(graders.judge(answer), releases(answer));
            REQUIRE(releases(answer).passed);
            require_alike(graders.judge(stub), releases(stub));
            REQUIRE_FALSE(releases(stub).passed);
        }
    }
    std::filesystem::remove_all(folder);
}

TEST_CASE("a public case file names the line of a case whose judge is unknown") {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / "raystep-public-checks-bad-test";
    std::filesystem::remove_all(folder);
    PublicCheck check{"stage1.unit", 1, "unit", "vectors", {}};
    check.cases.push_back(
        {"dot", {"dot", probe::Json::array()}, {{"judge", "threw"}, {"type", "x"}}, ""});
    check.cases.push_back({"dot", {"dot", probe::Json::array()}, {{"judge", "no_such_judge"}}, ""});
    write_public_check(check, folder);
    const std::string file = (folder / "stage1.unit.json").string();
    REQUIRE_THROWS_WITH(read_public_check(file),
                        Catch::StartsWith(file + ":3: case 1: no judge named 'no_such_judge'"));
    std::filesystem::remove_all(folder);
}
