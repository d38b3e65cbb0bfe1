#include "grader/report/html_report.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "app/protocol/base64.h"
#include "app/report/report_text.h"
#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"
#include "report_example.h"
#include "xml_document.h"

using namespace raystep::grade;
using raystep::base64;
using raystep::testing::example_report;
using raystep::testing::kHiddenSecret;
using raystep::testing::kHostile;
using raystep::testing::ScratchFolder;
using raystep::testing::XmlDocument;

namespace {

using Strings = std::vector<std::string>;

std::string read(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

// A URL path's percent escapes decoded: what the browser asks the file system for.
std::string url_decoded(const std::string& url) {
    std::string path;
    for (std::size_t k = 0; k < url.size(); ++k) {
        if (url[k] == '%' && k + 2 < url.size()) {
            path += static_cast<char>(std::stoi(url.substr(k + 1, 2), nullptr, 16));
            k += 2;
        } else {
            path += url[k];
        }
    }
    return path;
}

// The example report's page, its images written into the folder, in one audience's view: the
// student's self-contained, the instructor's linking to the images.
std::string written(const std::filesystem::path& folder, Audience audience,
                    std::string chart = "") {
    raystep::testing::write_example_images(folder);
    HtmlReportOptions options;
    options.audience = audience;
    options.self_contained = audience == Audience::student;
    options.speed_error_chart_svg = std::move(chart);
    return html_report(example_report(), folder, options);
}

}  // namespace

TEST_CASE("html_report: one well-formed page with no script", "[report]") {
    const ScratchFolder scratch("html-report-test");
    const std::string html = written(scratch.path(), Audience::instructor);
    const XmlDocument page(html);
    INFO(page.errors());
    REQUIRE(page.well_formed());
    CHECK(page.count("//script") == 0);
    CHECK(lower(html).find("<script") == std::string::npos);
    CHECK(page.count("//*[@onerror or @onload or @onclick]") == 0);
    CHECK_THAT(html, Catch::Matchers::StartsWith("<!DOCTYPE html>\n<html lang=\"en\">"));
    // Self-contained: styles inline, nothing fetched from elsewhere.
    CHECK(page.count("//link") == 0);
    CHECK(page.count("//style") == 1);
    CHECK_THAT(page.values("//meta[@http-equiv='Content-Security-Policy']/@content").at(0),
               Catch::Matchers::StartsWith("default-src 'none'"));
    CHECK(lower(html).find("http://") == std::string::npos);
    CHECK(lower(html).find("https://") == std::string::npos);
}

TEST_CASE("html_report: the header, the stage table and a section per check", "[report]") {
    const ScratchFolder scratch("html-report-test");
    const XmlDocument page(written(scratch.path(), Audience::instructor));
    REQUIRE(page.well_formed());
    CHECK(page.values("//header//h1") == Strings{"alice <b>& \"bob\""});
    CHECK(page.values("//title") == Strings{"raystep grade: alice <b>& \"bob\", 16.5 / 40"});
    CHECK(page.values("//table[@class='scores']/tbody/tr/td[1]") ==
          Strings{"stage 1", "stage 2", "stage 3", "stage 4", "stage 5", "stage 6", "stage 7",
                  "pipeline"});
    CHECK(page.values("//table[@class='scores']/tfoot/tr/td[1]") == Strings{"16.5 / 40"});
    CHECK(page.count("//article") == 12);
    CHECK(page.values("//article[@id='check-3']//span[contains(@class, 'badge')]") ==
          Strings{"not implemented"});
    CHECK(page.values("//article[contains(@class, 'did-not-compile')]//details/@open") ==
          Strings{"open"});
    CHECK_THAT(page.values("//article[contains(@class, 'did-not-compile')]//pre").at(0),
               Catch::Matchers::Contains("&& <iostream>"));
    CHECK(page.values("//section[@id='stage-7']//table[@class='metrics']//th") ==
          Strings{"flip", "mae", "over_threshold", "psnr", "rmse"});
    CHECK(page.values("//span[@class='visibility']") ==
          Strings{"hidden", "after_due_date", "after_published"});
}

TEST_CASE("html_report: render checks show their three images side by side", "[report]") {
    const ScratchFolder scratch("html-report-test");
    const std::filesystem::path& folder = scratch.path();
    const XmlDocument page(written(scratch.path(), Audience::instructor));
    REQUIRE(page.well_formed());
    const Strings sources = page.values("//section[@id='stage-7']//div[@class='images']//img/@src");
    CHECK(sources == Strings{"render/mirrors%20reference.png",
                             "render/mirrors%20student%20%231.png",
                             "render/mirrors-difference.png"});
    for (const std::string& source : sources) {
        CAPTURE(source);
        CHECK(std::filesystem::exists(folder / url_decoded(source)));
    }
    CHECK(page.values("//section[@id='stage-7']//figcaption") ==
          Strings{"reference", "student", "difference"});
    // A missing image is a box naming it, not a broken picture.
    CHECK(page.values("//div[@class='missing-image']") ==
          Strings{"missing: render/shadows-student.png"});
}

TEST_CASE("html_report: counterexamples with their commands, hostile text as text", "[report]") {
    const ScratchFolder scratch("html-report-test");
    const XmlDocument page(written(scratch.path(), Audience::student));
    REQUIRE(page.well_formed());
    const std::string edges = "//article[.//code[text()='stage3.oracle.shared-edges']]";
    // The student's commands; the third counterexample has none, and shows none.
    CHECK(page.values(edges + "//table[@class='counterexamples']//tr[@class='reproduce']//code") ==
          Strings{"raystep check --stage 3 --family shared-edges --case 17",
                  "raystep check --stage 3 --family shared-edges --case 42"});
    CHECK(page.values(edges + "//tbody/tr[3]/td[4]") == Strings{displayable_text(kHostile)});
    CHECK_THAT(page.values("//article[contains(@class, 'crashed')]//pre").at(0),
               Catch::Matchers::EndsWith(displayable_text(kHostile)));
}

TEST_CASE("html_report: the student's page has no withheld check", "[report]") {
    const ScratchFolder scratch("html-report-test");
    const std::string html = written(scratch.path(), Audience::student);
    CHECK_THAT(html, !Catch::Matchers::Contains(kHiddenSecret));
    const XmlDocument page(html);
    REQUIRE(page.well_formed());
    CHECK(page.count("//article") == 9);
    CHECK(page.count("//span[@class='visibility']") == 0);
    CHECK_THAT(page.values("//p[@class='note']").at(0),
               Catch::Matchers::StartsWith("3 checks are not shown here"));
    CHECK(page.values("//table[@class='scores']/tfoot/tr/td[1]") == Strings{"12.5 / 32"});
}

TEST_CASE("html_report: a chart gets its own section after the stage table, none without one",
          "[report]") {
    const ScratchFolder scratch("html-report-test");
    CHECK_THAT(written(scratch.path(), Audience::student),
               !Catch::Matchers::Contains("speed-versus-error"));
    const std::string svg =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"100\"><text x=\"10\" "
        "y=\"50\">chart</text></svg>";
    const XmlDocument page(written(scratch.path(), Audience::student, svg));
    INFO(page.errors());
    REQUIRE(page.well_formed());
    CHECK(page.values("//section[@id='speed-versus-error']/h2") == Strings{"Speed versus error"});
    CHECK(page.values("//section[@id='speed-versus-error']/*[local-name()='svg']") ==
          Strings{"chart"});
    // After the stage table, before the first stage's checks.
    CHECK(page.count("//section[@id='speed-versus-error']/preceding-sibling::section/table") == 1);
}

TEST_CASE("html_report: the student's page carries its images inside it as data URLs", "[report]") {
    const ScratchFolder scratch("html-report-test");
    const XmlDocument page(written(scratch.path(), Audience::student));
    REQUIRE(page.well_formed());
    CHECK(page.values("//meta[@http-equiv='Content-Security-Policy']/@content") ==
          Strings{"default-src 'none'; img-src data:; style-src 'unsafe-inline'"});
    // The visible render checks' images, three each: the withheld check's are not in it.
    const Strings sources = page.values("//img/@src");
    CHECK(sources.size() == 6);
    for (const std::string& source : sources)
        CHECK_THAT(source, Catch::Matchers::StartsWith("data:image/png;base64,"));
    CHECK(page.values("//section[@id='stage-7']//img/@src").at(1) ==
          "data:image/png;base64," +
              base64(read(scratch.path() / "render/mirrors student #1.png")));

    // An image that is not there is a box naming it, as on the linked page.
    GradeReport report = example_report();
    for (CheckResult& check : report.checks)
        check.visibility = Visibility::visible;
    const XmlDocument every_check(html_report(report, scratch.path(), {}));
    CHECK(every_check.values("//div[@class='missing-image']") ==
          Strings{"missing: render/shadows-student.png"});
}

TEST_CASE("html_report: the student's page has the student's commands, the instructor's both",
          "[report]") {
    const ScratchFolder scratch("html-report-test");
    const std::string student = written(scratch.path(), Audience::student);
    CHECK_THAT(student, !Catch::Matchers::Contains("raystep-grade submission"));
    const XmlDocument page(written(scratch.path(), Audience::instructor));
    REQUIRE(page.well_formed());
    const std::string mirrors = "//article[.//code[text()='stage7.render.mirrors']]";
    CHECK(page.values(mirrors + "//tr[@class='reproduce']/td[2]") ==
          Strings{"reproduce: raystep-grade submission 'submissions/alice & bob.zip' --check "
                  "stage7.render.mirrors --case 0 --instructor",
                  "the student's command: raystep trace scenes/stage7/mirrors.test 31 12 "
                  "--compare"});
}
