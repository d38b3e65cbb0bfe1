#pragma once

#include <cstddef>
#include <string>

#include "app/report/audience.h"
#include "app/report/grade_report.h"

namespace raystep::grade {

/// What a check found, as plain text for the reports that give a check one box of text
/// (Gradescope's and PrairieLearn's test output, JUnit's failure text): each counterexample with
/// its input, expected and received answers and the audience's command that reproduces it
/// (reproduce_command, audience.h; no line when there is none), then the details (a compiler's
/// first lines, a crash's signal), then the metrics. Not the summary, which each format has its
/// own place for. Displayable (report_text.h), each field clipped, the whole at most about
/// max_bytes; empty when the check found nothing to show.
std::string check_findings(const CheckResult& check, Audience audience, std::size_t max_bytes);

}  // namespace raystep::grade
