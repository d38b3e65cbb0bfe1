// The grader's render checks and `raystep compare` judge a render alike: the rubric gives full
// marks from the share of matching pixels at which raystep compare passes (a student release has
// no rubric, so the number lives in app/compare/render_rule.h), and on the images a render check
// writes into its report, raystep compare's rule gives the check's verdict, summary and metrics.
// On sampled views the rubric's number is the share of tiles (app/compare/sampled_reference.h).

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "app/compare/render_rule.h"
#include "app/compare/sampled_reference.h"
#include "app/grade/rubric.h"
#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"
#include "grader/grade/check_definition.h"
#include "grader/grade/checks/stage_checks.h"

using namespace raystep;
namespace fs = std::filesystem;

TEST_CASE("rubric: every render check has full marks where raystep compare passes", "[grader]") {
    const grade::Rubric rubric = grade::load_rubric(RAYSTEP_RUBRIC);
    std::set<std::string> noisy;
    for (const grade::CheckDefinition& check : grade::noisy_render_checks())
        noisy.insert(check.id);
    std::size_t render_checks = 0;
    for (const grade::CheckDefinition& check : grade::all_checks()) {
        if (check.kind != "render") continue;
        CAPTURE(check.id);
        ++render_checks;
        // The noisy ones (noisy_render_checks.cpp: stage 8's sampled scenes, stage 10's paths):
        // full marks from the share of tiles within the bound at which raystep compare passes a
        // sampled view.
        const bool sampled = noisy.count(check.id) > 0;
        const double allowed = sampled ? kSampledTilesApartAllowed : kDifferingShareAllowed;
        CHECK(rubric.entry(check.id).full_at == Approx(1.0 - allowed).margin(1e-12));
    }
    CHECK(render_checks > 0);
}

TEST_CASE(
    "render check and raystep compare: one verdict, summary and metrics on the check's images",
    "[grader]") {
    const std::vector<grade::CheckDefinition> checks = grade::all_checks();
    const auto check = std::find_if(checks.begin(), checks.end(), [](const auto& definition) {
        return definition.id == "stage2.render.orthographic.rays";
    });
    REQUIRE(check != checks.end());

    // The reference probe stands in for a submission: the check renders the view with it and
    // writes the reference's and the "student's" images into the report folder.
    const raystep::testing::ScratchFolder report("render-compare");
    grade::GradingContext context;
    context.source = RAYSTEP_SOURCE_DIR;
    context.report_folder = report.path();
    context.reproduce = "raystep-grade submission test";
    grade::BuiltProbe probe;
    probe.program = fs::path(RAYSTEP_REFERENCE_PROBE);
    const grade::CheckMeasure measure = check->measure(context, probe);
    REQUIRE_FALSE(measure.images.student.empty());

    const RenderFileVerdict compared = judge_render_files(report.path() / measure.images.student,
                                                          report.path() / measure.images.reference);
    CHECK((measure.outcome == grade::Outcome::passed) == compared.verdict.passed);
    CHECK(measure.summary == render_summary(compared.verdict));
    const auto metrics = render_metrics(compared.verdict.diff);
    CHECK(measure.metrics == std::map<std::string, double>(metrics.begin(), metrics.end()));
}
