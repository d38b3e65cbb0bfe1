#include "grader/grade/write_reports.h"

#include <fstream>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "app/report/audience.h"
#include "grader/grade/build_locations.h"
#include "grader/grade/report_json.h"
#include "grader/grade/speed_error_chart.h"
#include "grader/report/gradescope_results.h"
#include "grader/report/html_report.h"
#include "grader/report/junit_xml.h"
#include "grader/report/prairielearn_results.h"
#include "grader/report/student_results.h"

namespace raystep::grade {

namespace fs = std::filesystem;

namespace {

void write_file(const fs::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error(file.string() + ": cannot be written");
}

void make_folder(const fs::path& folder) {
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) throw std::runtime_error(folder.string() + ": cannot be made: " + error.message());
}

}  // namespace

void write_reports(const GradeReport& report, const fs::path& output) {
    const fs::path student = student_folder(output);
    const fs::path instructor = instructor_folder(output);
    make_folder(student);
    make_folder(instructor);

    // The student's folder: every file made from the student's view alone. The chart too, so
    // that a withheld speed check's measurements stay out of it; drawn once when both views
    // hold the same.
    const std::optional<nlohmann::json> student_chart =
        speed_error_chart_data(seen_by(report, Audience::student), built_pareto_reference());
    const std::optional<nlohmann::json> instructor_chart =
        speed_error_chart_data(report, built_pareto_reference());
    HtmlReportOptions student_page;
    if (student_chart) student_page.speed_error_chart_svg = draw_chart_svg(*student_chart);
    write_file(student / "index.html", html_report(report, instructor, student_page));
    write_file(student / "results.json", student_results(report).dump(2) + "\n");
    write_file(student / "junit.xml", junit_xml(report, Audience::student));

    HtmlReportOptions instructor_page;
    instructor_page.audience = Audience::instructor;
    instructor_page.self_contained = false;
    if (instructor_chart) {
        instructor_page.speed_error_chart_svg = instructor_chart == student_chart
                                                    ? student_page.speed_error_chart_svg
                                                    : draw_chart_svg(*instructor_chart);
    }
    write_file(instructor / "instructor.html", html_report(report, instructor, instructor_page));
    write_file(instructor / "results.json", gradescope_results(report).dump(2) + "\n");
    write_file(instructor / "prairielearn.json",
               prairielearn_results(report, instructor).dump(2) + "\n");
    write_file(instructor / "junit.xml", junit_xml(report, Audience::instructor));
    // Last: a complete report.json is how a resumed batch knows this submission is done.
    // The report keeps a submission's text as it was, which may not be UTF-8: such bytes are
    // written as U+FFFD rather than stop the report.
    write_file(
        finished_report_file(output),
        report_json(report).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

}  // namespace raystep::grade
