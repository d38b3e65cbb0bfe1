// The public checks a student release holds as data (grading/public/): each written, read back
// and judged the same as the grader judges it, and each passed by the reference (a render pixel
// for pixel, since the release's reference is the grader's render at the grader's size).

#include <filesystem>

#include "base/testing/catch.h"

#include "app/grade/data_judge.h"
#include "app/grade/public_case.h"
#include "app/grade/public_check_run.h"
#include "app/grade/render_judge.h"
#include "app/grade/rubric.h"
#include "app/grade/value_judges.h"
#include "app/probe/call_reply.h"
#include "app/protocol/image_json.h"
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
    // The render cases name their scenes from the repository's root, as `raystep grade` does.
    std::filesystem::current_path(RAYSTEP_SOURCE_DIR);
    const Rubric rubric = load_rubric(RAYSTEP_RUBRIC);
    const probe::CallTable reference = probe::stage_calls();
    ProbeAnswer stub;
    stub.kind = ProbeAnswer::Kind::threw;
    stub.exception_type = "other";
    stub.message = "an answer no judge takes";
    const std::vector<PublicCheck> checks = public_checks(RAYSTEP_SOURCE_DIR);
    REQUIRE_FALSE(checks.empty());
    for (const PublicCheck& written : checks) {
        INFO(written.id);
        // A sample is worth nothing and has no rubric entry; every other check is scored.
        if (written.kind == kSampleKind) {
            REQUIRE(rubric.checks.count(written.id) == 0);
            const CheckResult run =
                run_public_check(written, rubric, reference, RAYSTEP_SOURCE_DIR);
            REQUIRE(run.outcome == Outcome::passed);
            REQUIRE(run.max_score == 0.0);
        } else {
            REQUIRE(rubric.entry(written.id).points > 0);
        }
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
            const Verdict verdict = releases(answer);
            REQUIRE(verdict.passed);
            // A render judged against the image the grader compares with: every pixel the same.
            if (verdict.fraction) REQUIRE(*verdict.fraction == 1.0);
            require_alike(graders.judge(stub), releases(stub));
            REQUIRE_FALSE(releases(stub).passed);
        }
    }
    std::filesystem::remove_all(folder);
}

TEST_CASE("raystep grade scores a check by the grader's rule: full points read passed") {
    // Nine of ten dot products right against a rubric that pays in full from 0.9: the grader calls
    // that passed (scored_check), and so must a student's `raystep grade`.
    PublicCheck check{"stage1.unit", 1, "unit", "vectors", {}};
    for (int k = 0; k < 10; ++k) {
        const double expected = k == 0 ? 1.0 : 32.0;
        check.cases.push_back(
            {"dot",
             {"dot", probe::Json::array({probe::vec3({1, 2, 3}), probe::vec3({4, 5, 6})})},
             near_number_judge(expected, 0.0),
             ""});
    }
    Rubric rubric;
    rubric.checks["stage1.unit"] = {3.0, 0.9, 0.5, Visibility::visible};
    const CheckResult result =
        run_public_check(check, rubric, probe::stage_calls(), RAYSTEP_SOURCE_DIR);
    REQUIRE(result.outcome == Outcome::passed);
    REQUIRE(result.score == 3.0);
    REQUIRE(result.counterexamples.size() == 1);
    // Paid in full only at 1.0, and nothing at 0.7, the same nine earn 2 of 3 points and fail.
    rubric.checks["stage1.unit"].full_at = 1.0;
    rubric.checks["stage1.unit"].zero_at = 0.7;
    const CheckResult short_of_full =
        run_public_check(check, rubric, probe::stage_calls(), RAYSTEP_SOURCE_DIR);
    REQUIRE(short_of_full.outcome == Outcome::failed);
    REQUIRE(short_of_full.score == Approx(2.0));
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

TEST_CASE("a render the release judges wrong names its worst pixel and the trace that shows it") {
    Image reference(4, 2);
    reference.set(3, 1, Color(1, 0.5, 0));
    const Judge judge =
        build_judge(render_judge(reference, "stage2/orthographic.test", View::rays, 320, 160));
    ProbeAnswer answer;
    answer.kind = ProbeAnswer::Kind::result;
    answer.value = probe::image(Image(4, 2));
    const Verdict verdict = judge(answer);
    REQUIRE_FALSE(verdict.passed);
    REQUIRE(verdict.fraction == 7.0 / 8.0);
    REQUIRE(verdict.place ==
            "stage2/orthographic.test, rays view, pixel (3, 1) of the 4 x 2 render, pixel (280, "
            "120) at the scene's 320 x 160");
    REQUIRE(verdict.expected == "(1, 0.5, 0)");
    REQUIRE(verdict.got == "(0, 0, 0)");
    REQUIRE(verdict.place_reproduce ==
            "build/student/bin/raystep trace scenes/stage2/orthographic.test 280 120 --view rays");
}
