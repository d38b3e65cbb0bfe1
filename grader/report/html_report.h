#pragma once

#include <filesystem>
#include <string>

#include "grader/report/audience.h"
#include "grader/report/grade_report.h"

namespace raystep::grade {

struct HtmlReportOptions {
    /// Whose page it is. The student's, by default, so that a page written without thought never
    /// shows a hidden check.
    Audience audience = Audience::student;

    /// The speed-versus-error chart (docs/design, "Reports"; made by issue 7) as one inline
    /// <svg> element, placed after the stage table under "Speed versus error". Inserted as it is,
    /// so it must be made by raystep's own code from the speed checks' metrics, with any text
    /// from a submission escaped, and be well-formed XML like the rest of the page. Empty: the
    /// page has no chart section.
    std::string speed_error_chart_svg;
};

/// The report as one self-contained HTML page (inline CSS, no script, no network; it is also
/// well-formed XML): the student and total, a table of scores per stage, the chart if given,
/// then per stage a section for each check with its outcome, score, id, summary, metrics, for a
/// render check the reference, student and difference images side by side, its counterexamples
/// with the command that reproduces each, and its details. Every text from the report is escaped
/// (markup_escape.h); a Content-Security-Policy forbids scripts besides. For the student, the
/// checks they are not shown (audience.h) are left out, and a note says how many there are.
///
/// The images' paths (RenderImages) are relative to `folder`: a missing image shows as a box
/// naming its path.
std::string html_report(const GradeReport& report, const std::filesystem::path& folder,
                        const HtmlReportOptions& options);

/// Writes html_report to folder/index.html, making the folder if needed, and returns that path.
/// Throws std::runtime_error naming the file when it cannot be written.
std::filesystem::path write_html_report(const GradeReport& report,
                                        const std::filesystem::path& folder,
                                        const HtmlReportOptions& options = {});

}  // namespace raystep::grade
