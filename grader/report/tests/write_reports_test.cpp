#include "grader/grade/write_reports.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/report/report_text.h"
#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/grade/report_json.h"
#include "grader/report/markup_escape.h"
#include "report_example.h"
#include "xml_document.h"

using namespace raystep::grade;
using raystep::testing::example_report;
using raystep::testing::kHiddenSecret;
using raystep::testing::ScratchFolder;
using raystep::testing::XmlDocument;

namespace fs = std::filesystem;

namespace {

std::string file_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Every file under the folder, by its path relative to it.
std::set<std::string> files_under(const fs::path& folder) {
    std::set<std::string> files;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder)) {
        if (entry.is_regular_file()) files.insert(fs::relative(entry.path(), folder).string());
    }
    return files;
}

// The report written as raystep-grade writes it, its render images where the checks put them.
fs::path write_example_reports(const fs::path& output,
                               const GradeReport& report = example_report()) {
    raystep::testing::write_example_images(instructor_folder(output));
    write_reports(report, output);
    return output;
}

// A text as each report may carry it: as it is, made displayable, escaped for XML and HTML, and
// escaped for JSON.
std::vector<std::string> forms_of(const std::string& text) {
    const std::string shown = displayable_text(text);
    const std::string json = nlohmann::json(shown).dump();
    return {text, shown, markup_text(shown), json.substr(1, json.size() - 2)};
}

// What a student's file must not hold of a check they are not shown: its id, and each of its
// counterexamples' inputs and commands.
std::vector<std::string> secrets_of(const CheckResult& check) {
    std::vector<std::string> secrets = {check.id};
    for (const Counterexample& example : check.counterexamples) {
        for (const std::string* text : {&example.input, &example.student_reproduce}) {
            for (std::string& form : forms_of(*text))
                secrets.push_back(std::move(form));
        }
    }
    return secrets;
}

// The secrets of the report's withheld checks that a file holds.
std::vector<std::string> leaks_in(const std::string& text, const GradeReport& report) {
    std::vector<std::string> leaks;
    for (const CheckResult& check : report.checks) {
        if (check.visibility == Visibility::visible) continue;
        for (const std::string& secret : secrets_of(check)) {
            if (text.find(secret) != std::string::npos) leaks.push_back(secret);
        }
    }
    return leaks;
}

}  // namespace

TEST_CASE("write_reports: the student's folder and the instructor's, and nothing else",
          "[report]") {
    const ScratchFolder scratch("write-reports-test");
    const fs::path output = write_example_reports(scratch.path() / "out");
    CHECK(files_under(student_folder(output)) ==
          std::set<std::string>{"index.html", "junit.xml", "results.json"});
    CHECK(files_under(instructor_folder(output)) ==
          std::set<std::string>{"instructor.html", "junit.xml", "prairielearn.json", "report.json",
                                "results.json", "render/mirrors reference.png",
                                "render/mirrors student #1.png", "render/mirrors-difference.png",
                                "render/mirrors-difference-none.png",
                                "render/shadows-reference.png"});
    std::set<std::string> top;
    for (const fs::directory_entry& entry : fs::directory_iterator(output))
        top.insert(entry.path().filename().string());
    CHECK(top == std::set<std::string>{"instructor", "student"});
    CHECK(finished_report_file(output) == output / "instructor" / "report.json");
}

TEST_CASE("write_reports: no student's file names a withheld check or its inputs", "[report]") {
    const ScratchFolder scratch("write-reports-test");
    const GradeReport report = example_report();
    const fs::path output = write_example_reports(scratch.path() / "out", report);
    for (const std::string& file : files_under(student_folder(output))) {
        CAPTURE(file);
        const std::string text = file_text(student_folder(output) / file);
        CHECK(leaks_in(text, report).empty());
        CHECK(text.find(kHiddenSecret) == std::string::npos);
        // Nor the instructor's commands, which need the grader.
        CHECK(text.find("raystep-grade submission") == std::string::npos);
    }

    // The same checks made visible are found in every student's file: the search above looks
    // for what the files would hold.
    GradeReport every_check_shown = report;
    for (CheckResult& check : every_check_shown.checks)
        check.visibility = Visibility::visible;
    const fs::path shown = write_example_reports(scratch.path() / "shown", every_check_shown);
    for (const std::string& file : files_under(student_folder(shown))) {
        CAPTURE(file);
        const std::string text = file_text(student_folder(shown) / file);
        for (const CheckResult& check : report.checks) {
            if (check.visibility == Visibility::visible) continue;
            CAPTURE(check.id);
            CHECK(text.find(check.id) != std::string::npos);
            // JUnit XML gives counterexamples only to the checks that did not pass.
            if (file == "junit.xml" && check.outcome == Outcome::passed) continue;
            const std::vector<std::string> inputs = forms_of(check.counterexamples.at(0).input);
            CHECK(std::any_of(inputs.begin(), inputs.end(), [&](const std::string& input) {
                return text.find(input) != std::string::npos;
            }));
        }
    }
}

TEST_CASE("write_reports: no student's file holds a time that counts the withheld checks",
          "[report]") {
    // A check's time depends on its inputs: a submission can take as long as a hidden input says.
    // The checks' phase, with the withheld ones, took 4321.5 s here; the shown ones, a second.
    const ScratchFolder scratch("write-reports-test");
    GradeReport report = example_report();
    report.times.checks = 4321.5;
    const fs::path output = write_example_reports(scratch.path() / "out", report);
    for (const std::string& file : files_under(student_folder(output))) {
        CAPTURE(file);
        const std::string text = file_text(student_folder(output) / file);
        CHECK(text.find("4321") == std::string::npos);  // the phase
        CHECK(text.find("4334") == std::string::npos);  // the whole run: 4334.35 s
    }
    CHECK(file_text(finished_report_file(output)).find("4321.5") != std::string::npos);
}

TEST_CASE("write_reports: the student's page is one file, and its JUnit XML is valid", "[report]") {
    const ScratchFolder scratch("write-reports-test");
    const fs::path output = write_example_reports(scratch.path() / "out");
    const XmlDocument page(file_text(student_folder(output) / "index.html"));
    REQUIRE(page.well_formed());
    const std::vector<std::string> sources = page.values("//img/@src");
    CHECK(sources.size() == 6);
    for (const std::string& source : sources)
        CHECK_THAT(source, Catch::Matchers::StartsWith("data:image/png;base64,"));
    // The instructor's page links its images, which sit beside it.
    const XmlDocument instructor(file_text(instructor_folder(output) / "instructor.html"));
    for (const std::string& source : instructor.values("//img/@src"))
        CHECK_THAT(source, Catch::Matchers::StartsWith("render/"));

    const fs::path schema = RAYSTEP_JUNIT_SCHEMA;
    CHECK(XmlDocument(file_text(student_folder(output) / "junit.xml")).schema_violations(schema) ==
          "");
    CHECK(
        XmlDocument(file_text(instructor_folder(output) / "junit.xml")).schema_violations(schema) ==
        "");
    const nlohmann::json results =
        nlohmann::json::parse(file_text(student_folder(output) / "results.json"));
    CHECK(results.at("checks").size() == 9);
    // PrairieLearn's carries the visible render checks' images, which are the 8th and 9th tests.
    const nlohmann::json prairielearn =
        nlohmann::json::parse(file_text(instructor_folder(output) / "prairielearn.json"));
    CHECK(prairielearn.at("tests")[7].at("name") == "stage7.render.mirrors");
    CHECK(prairielearn.at("tests")[7].at("images").size() == 3);
    CHECK(prairielearn.at("tests")[8].at("images").size() == 3);
}

// The chart is drawn by scripts/draw-charts.py where CMake found a Python with matplotlib.
TEST_CASE("write_reports: a speed-against-error measurement puts the drawn chart in both pages",
          "[report]") {
    GradeReport report = example_report();
    CheckResult speed;
    speed.id = kSpeedErrorCheck;
    speed.stage = 3;
    speed.outcome = Outcome::passed;
    speed.metrics = {{kSpeedErrorCases, 2000},    {kSpeedErrorFalseHits, 0},
                     {kSpeedErrorFalseMisses, 0}, {kSpeedErrorUlpsMedian, 1},
                     {kSpeedErrorUlpsP99, 20},    {kSpeedErrorAgainstCramer, 1.0}};
    report.checks.push_back(speed);
    const ScratchFolder scratch("write-reports-test");
    const fs::path output = write_example_reports(scratch.path() / "out", report);
    const bool drawn = !std::string(RAYSTEP_CHART_PYTHON).empty();
    for (const fs::path& page_file :
         {student_folder(output) / "index.html", instructor_folder(output) / "instructor.html"}) {
        const XmlDocument page(file_text(page_file));
        INFO(page_file << ": " << page.errors());
        REQUIRE(page.well_formed());
        const std::string chart = "//section[@id='speed-versus-error']/*[local-name()='svg']";
        CHECK(page.count(chart) == (drawn ? 1 : 0));
        if (drawn) {
            CHECK_THAT(file_text(page_file), Catch::Matchers::Contains("your intersect_triangle"));
        }
    }
}

TEST_CASE("write_reports: report.json in the instructor's folder reads back as the report",
          "[report]") {
    const ScratchFolder scratch("write-reports-test");
    const GradeReport report = example_report();
    const fs::path output = write_example_reports(scratch.path() / "out", report);
    const GradeReport back =
        report_from_json(nlohmann::json::parse(file_text(finished_report_file(output))));
    REQUIRE(back.checks.size() == report.checks.size());
    CHECK(back.score() == report.score());
    CHECK(back.checks[3].seconds == report.checks[3].seconds);
    CHECK(back.checks[3].counterexamples[0].student_reproduce ==
          report.checks[3].counterexamples[0].student_reproduce);
}

TEST_CASE("write_reports: a folder that cannot be made is an error naming it", "[report]") {
    const ScratchFolder scratch("write-reports-test");
    const fs::path blocker = scratch.path() / "blocker";
    std::ofstream(blocker) << "a file where the folder should be";
    CHECK_THROWS_WITH(write_reports(example_report(), blocker / "out"),
                      Catch::Matchers::Contains((blocker / "out").string()));
}
