#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace raystep::grade {

// Text that every report writer shares: what a submission wrote made safe to show, long text
// clipped, and the few numbers and labels every report prints the same way.

/// How much of one counterexample field or one summary a report shows: enough for a readable
/// call and answer, little enough that a submission printing megabytes cannot swell a report.
constexpr std::size_t kMaxFieldBytes = 2000;

/// How much of a check's details (a compiler's first lines, a crash's signal) a report shows.
constexpr std::size_t kMaxDetailsBytes = 8000;

/// The text as valid UTF-8 with nothing in it that could act on a reader: every byte that is not
/// part of a valid UTF-8 sequence, every control character but tab and newline (C0, DEL, C1: a
/// terminal's escape sequences and carriage returns that overwrite a line), the bidirectional
/// overrides and isolates (which reorder what follows them) and U+FFFE and U+FFFF (not XML
/// characters) become U+FFFD. A carriage return before a newline is dropped. What remains is
/// printable on a terminal and legal in JSON, XML 1.0 and HTML.
std::string displayable_text(std::string_view text);

/// displayable_text of the text's start, at most max_bytes bytes of whole characters, followed by
/// " [... N more bytes]" when the rest, N bytes of the text, was left out. Only the part shown is
/// examined, so clipping megabytes costs what the part shown costs.
std::string clipped_text(std::string_view text, std::size_t max_bytes);

/// A score with at most two decimals and no trailing zeros: "2.5", "10", "0.33".
std::string score_text(double score);

/// score_text of a score, except that a score below its maximum never reads as the maximum:
/// 0.998 out of 1 is "0.99".
std::string score_below_max_text(double score, double max_score);

/// "2.5 / 10": score_below_max_text of the score, out of score_text of the maximum.
std::string score_out_of(double score, double max_score);

/// A metric with four significant digits: "34.12", "0.001234", "1.5e+06", "inf", "nan".
std::string metric_text(double value);

/// "stage 3"; "pipeline" for stage 0, the checks of the student's whole pipeline.
std::string stage_label(int stage);

/// The sentence every report leads with when a submission's files could not all be taken
/// (GradeReport::intake_problem): "The submission's files could not all be taken: WHY",
/// displayable and clipped; empty when there was no problem.
std::string intake_problem_line(std::string_view problem);

}  // namespace raystep::grade
