#pragma once

#include <filesystem>
#include <string>

#include "app/report/audience.h"
#include "app/report/grade_report.h"

namespace raystep::grade {

struct HtmlReportOptions {
    /// Whose page it is. The student's, by default, so that a page written without thought never
    /// shows a hidden check.
    Audience audience = Audience::student;

    /// The images inside the page as data URLs, so that the one file can be sent or uploaded
    /// alone (the student's page). false: the page links to the image files, by their paths
    /// relative to the page, which must then sit in the images' folder (the instructor's page).
    bool self_contained = true;

    /// The speed-versus-error chart (docs/measurements/pareto.md, "In the grader's report") as one
    /// inline <svg> element, placed after the stage table under "Speed versus error". Inserted as
    /// it is, so it must be drawn by raystep's own script (grader/grade/speed_error_chart.h) from
    /// the speed checks' metrics the page's audience is shown, with no text from a submission,
    /// and be well-formed XML like the rest of the page. Empty: the page has no chart section.
    std::string speed_error_chart_svg;
};

/// The report as one HTML page (inline CSS, no script, no network; it is also well-formed XML):
/// the student and total, the intake problem if there was one (GradeReport::intake_problem), a
/// table of scores per stage, the chart if given, then per stage a section for each check with
/// its outcome, score, id, summary, metrics, for a render check the reference, student and
/// difference images side by side, its counterexamples with the audience's command that
/// reproduces each (reproduce_command, audience.h; the instructor also sees the student's), and
/// its details. Every text from the report is escaped (markup_escape.h); a
/// Content-Security-Policy forbids scripts besides. For the student, the checks they are not
/// shown (audience.h) are left out, and a note says how many there are.
///
/// The images' paths (RenderImages) are relative to `images_folder`, where they are read from
/// for a self-contained page: a missing image shows as a box naming its path.
std::string html_report(const GradeReport& report, const std::filesystem::path& images_folder,
                        const HtmlReportOptions& options);

}  // namespace raystep::grade
