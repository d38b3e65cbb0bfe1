#pragma once

#include "app/report/grade_report.h"

namespace raystep::grade {

/// Who reads a report: the student, or the instructor, who sees every check.
enum class Audience { student, instructor };

/// True when the check is shown to this audience. A student is shown only `visible` checks: a
/// report cannot tell whether the due date has passed or the grades are published, so
/// `after_due_date` and `after_published` checks are withheld from a student like `hidden` ones
/// (Gradescope, which knows the dates, receives every check with its visibility and shows each
/// in time).
bool shown_to(const CheckResult& check, Audience audience);

/// The report as this audience sees it: the same, minus the checks it is not shown, so that its
/// scores add up only what the audience can see. Its times too: a check's time depends on its
/// inputs (a submission can take as long as a hidden input says), so when checks are withheld,
/// the checks' phase is the sum of the shown checks' times, and the reports' phase (which writes
/// the withheld checks' counterexamples for the instructor) is 0.
GradeReport seen_by(const GradeReport& report, Audience audience);

/// The command that reruns a counterexample, for this audience: for the student,
/// `student_reproduce` (what runs in the student release), never the instructor's `raystep-grade`
/// command, which needs the grader and the rubric; for the instructor, `reproduce`. Empty when
/// that audience has none: the report then shows no command.
const std::string& reproduce_command(const Counterexample& example, Audience audience);

}  // namespace raystep::grade
