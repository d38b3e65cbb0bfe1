#include "grader/report/prairielearn_results.h"

#include <filesystem>
#include <fstream>

#include "app/report/report_text.h"
#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"
#include "report_example.h"

using namespace raystep;
using namespace raystep::grade;
using raystep::testing::example_report;
using raystep::testing::kHiddenSecret;
using raystep::testing::kHostile;

namespace {

nlohmann::json prairielearn_written(const GradeReport& report) {
    return nlohmann::json::parse(prairielearn_results(report, {}).dump());
}

}  // namespace

// https://prairielearn.readthedocs.io/en/latest/externalGrading/, "Grading results".
TEST_CASE("prairielearn_results: the fields and types PrairieLearn reads", "[report]") {
    const nlohmann::json results = prairielearn_written(example_report());
    CHECK(results.at("gradable") == true);
    CHECK(results.at("score").is_number());
    CHECK(results.at("score").get<double>() == Approx(16.5 / 40.0));
    CHECK(results.at("message").is_string());
    CHECK(results.at("output").is_string());
    CHECK_FALSE(results.contains("format_errors"));
    REQUIRE(results.at("tests").is_array());
    for (const nlohmann::json& test : results.at("tests")) {
        CAPTURE(test.dump());
        CHECK(test.at("name").is_string());
        CHECK(test.at("description").is_string());
        CHECK(test.at("points").is_number());
        CHECK(test.at("max_points").is_number());
        CHECK(test.at("message").is_string());
        CHECK(test.at("output").is_string());
    }
}

TEST_CASE("prairielearn_results: withheld checks become one test per stage, points kept",
          "[report]") {
    const nlohmann::json results = prairielearn_written(example_report());
    const nlohmann::json& tests = results.at("tests");
    REQUIRE(tests.size() == 9 + 3);  // the visible checks, then stages 3, 6 and 7's withheld ones
    CHECK(tests[9].at("name") == "stage 3: hidden checks");
    CHECK(tests[9].at("points") == 0);
    CHECK(tests[9].at("max_points") == 4);
    CHECK(tests[9].at("output") == "");
    CHECK(tests[10].at("name") == "stage 6: hidden checks");
    CHECK(tests[11].at("name") == "stage 7: hidden checks");
    CHECK(tests[11].at("description") == "1 check whose name and inputs are not shown");
    double points = 0.0;
    double max_points = 0.0;
    for (const nlohmann::json& test : tests) {
        points += test.at("points").get<double>();
        max_points += test.at("max_points").get<double>();
    }
    CHECK(points / max_points == results.at("score").get<double>());
    // Nothing of the hidden check but its points.
    CHECK_THAT(results.dump(), !Catch::Matchers::Contains(kHiddenSecret));
}

TEST_CASE("prairielearn_results: a visible check's test", "[report]") {
    const nlohmann::json test = prairielearn_written(example_report()).at("tests")[3];
    CHECK(test.at("name") == "stage3.oracle.shared-edges");
    CHECK(test.at("description") == "rays through shared edges of closed meshes");
    CHECK(test.at("points") == 1.5);
    CHECK(test.at("max_points") == 5);
    CHECK_THAT(test.at("message").get<std::string>(),
               Catch::Matchers::StartsWith("failed: 97 of 100"));
    CHECK_THAT(
        test.at("output").get<std::string>(),
        Catch::Matchers::Contains("raystep check --stage 3 --family shared-edges --case 17") &&
            Catch::Matchers::Contains("--case 42") &&
            Catch::Matchers::Contains(displayable_text(kHostile)) &&
            !Catch::Matchers::Contains("raystep-grade"));
}

TEST_CASE("prairielearn_results: nothing compiled is not gradable, with the compiler's lines",
          "[report]") {
    GradeReport report;
    for (int stage = 1; stage <= 2; ++stage) {
        CheckResult check;
        check.id = "stage" + std::to_string(stage) + ".unit.x";
        check.stage = stage;
        check.outcome = Outcome::did_not_compile;
        check.max_score = 2;
        check.details = "error in stage " + std::to_string(stage);
        report.checks.push_back(check);
        report.checks.push_back(check);  // a stage's checks share its compiler output
    }
    const nlohmann::json results = prairielearn_written(report);
    CHECK(results.at("gradable") == false);
    CHECK(results.at("format_errors") == nlohmann::json({"error in stage 1", "error in stage 2"}));

    // One stage that compiles makes the submission gradable: the rest score zero.
    report.checks[0].outcome = Outcome::failed;
    CHECK(prairielearn_written(report).at("gradable") == true);
}

TEST_CASE("prairielearn_results: an empty report scores 0, and a huge one stays under 1 MB",
          "[report]") {
    CHECK(prairielearn_written(GradeReport{}).at("score") == 0.0);

    GradeReport huge;
    for (int k = 0; k < 300; ++k) {
        CheckResult check;
        check.id = "stage3.unit.case" + std::to_string(k);
        check.stage = 3;
        check.max_score = 1;
        check.details = std::string(1'000'000, 'd');
        check.counterexamples.assign(5, {std::string(100'000, 'i'), "e", kHostile, "r", "s"});
        huge.checks.push_back(check);
    }
    const std::string text = prairielearn_results(huge, {}).dump();
    CHECK(text.size() < 1'000'000);
}

TEST_CASE("prairielearn_results: render checks carry their images, failing ones first, under 1 MB",
          "[report]") {
    const testing::ScratchFolder scratch("prairielearn-test");
    const std::filesystem::path& folder = scratch.path();
    std::filesystem::create_directories(folder / "render");
    // 100 KB an image, 3 a check: one check's images as data URLs take about 400 KB.
    std::ofstream(folder / "render/large.png", std::ios::binary) << std::string(100'000, 'p');
    std::ofstream(folder / "render/small.png", std::ios::binary) << std::string(3, 'p');

    GradeReport report;
    for (int k = 0; k < 10; ++k) {
        CheckResult check;
        check.id = "stage6.render.scene" + std::to_string(k);
        check.stage = 6;
        check.kind = "render";
        check.outcome = k < 5 ? Outcome::passed : Outcome::failed;
        check.max_score = 1;
        check.images = {"render/large.png", "render/large.png", "render/large.png"};
        report.checks.push_back(check);
    }
    report.checks[9].images = {"render/small.png", "render/missing.png", ""};
    const std::string text = prairielearn_results(report, folder).dump();

    CHECK(text.size() < 1'000'000);
    const nlohmann::json tests = nlohmann::json::parse(text).at("tests");
    // The first failing check's images fit; the next failing one's would not, nor any passed
    // one's; the small image of the last fits beside them, its missing one left out.
    REQUIRE(tests[5].contains("images"));
    CHECK(tests[5].at("images").size() == 3);
    CHECK(tests[5].at("images")[0].at("label") == "reference");
    CHECK(tests[5].at("images")[2].at("label") == "difference");
    CHECK_THAT(tests[5].at("images")[1].at("url").get<std::string>(),
               Catch::Matchers::StartsWith("data:image/png;base64,cHBw"));
    CHECK(tests[9].at("images") ==
          nlohmann::json({{{"label", "reference"}, {"url", "data:image/png;base64,cHBw"}}}));
    for (const int k : {0, 4, 6, 8}) {
        CAPTURE(k);
        CHECK_FALSE(tests[k].contains("images"));
        CHECK_THAT(tests[k].at("output").get<std::string>(),
                   Catch::Matchers::Contains("The images are left out here"));
    }
}
