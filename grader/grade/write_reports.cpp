#include "grader/grade/write_reports.h"

#include <fstream>
#include <stdexcept>

#include "grader/grade/report_json.h"
#include "grader/grade/speed_error_chart.h"
#include "grader/report/gradescope_results.h"
#include "grader/report/html_report.h"
#include "grader/report/junit_xml.h"
#include "grader/report/prairielearn_results.h"

namespace raystep::grade {

namespace fs = std::filesystem;

void write_reports(const GradeReport& report, const fs::path& folder) {
    fs::create_directories(folder);
    const auto write = [&](const char* name, const std::string& text) {
        std::ofstream out(folder / name);
        out << text;
        if (!out) throw std::runtime_error((folder / name).string() + ": cannot be written");
    };
    write("results.json", gradescope_results(report).dump(2) + "\n");
    write("prairielearn.json", prairielearn_results(report).dump(2) + "\n");
    write("junit.xml", junit_xml(report, Audience::instructor));
    HtmlReportOptions student;
    student.speed_error_chart_svg = speed_error_chart_svg(report, RAYSTEP_PARETO_REFERENCE);
    write_html_report(report, folder, student);
    HtmlReportOptions instructor = student;
    instructor.audience = Audience::instructor;
    write("instructor.html", html_report(report, folder, instructor));
    // Last: a complete report.json is how a resumed batch knows this submission is done.
    write("report.json", report_json(report).dump(2) + "\n");
}

}  // namespace raystep::grade
