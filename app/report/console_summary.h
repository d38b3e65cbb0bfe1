#pragma once

#include <string>
#include <string_view>

#include "app/report/audience.h"
#include "app/report/grade_report.h"

namespace raystep::grade {

/// Columns the console summary fits in: the narrowest terminal still common. Only a reproduce
/// command runs longer, since a command broken over two lines does not paste back as one.
constexpr std::size_t kConsoleWidth = 80;

/// The scores per stage in a small table, with the number of checks passed and the total, for
/// the stages that have checks: 1 to kLastStage, then the whole pipeline. Counts every check in the
/// report given: pass seen_by(report, audience) for one audience's sums.
std::string stage_table(const GradeReport& report);

/// The grade for a terminal: who, the intake problem if there was one
/// (GradeReport::intake_problem), the total, the stage table, then per stage one line per check
/// (outcome, score, id, summary) and, under each check that did not pass, its first
/// counterexample with the audience's command that reproduces it (reproduce_command,
/// audience.h), or the first lines of its details. For the student, the checks they are not
/// shown (audience.h) are left out of every line and sum, and a closing line says how many there
/// are; the instructor sees them all, marked with their visibility.
std::string console_summary(const GradeReport& report, Audience audience);

/// A paragraph to print beside the summary (what `raystep grade` did not run), wrapped at
/// kConsoleWidth as the summary's own lines are, ending in a newline.
std::string console_paragraph(std::string_view text);

}  // namespace raystep::grade
