#include "app/report/console_summary.h"

#include <algorithm>
#include <string_view>
#include <vector>

#include "app/report/report_text.h"

namespace raystep::grade {

namespace {

// How many lines of a check's details (a compiler's output) the console shows: enough for the
// first error and its context; the HTML report has the rest.
constexpr std::size_t kDetailLines = 8;

// Indents: a check's line under its stage, and what belongs to a check under its line.
constexpr std::size_t kCheckIndent = 2;
constexpr std::size_t kFindingIndent = 6;

// Terminal columns of displayable UTF-8 text: one per character (wide characters are rare in a
// grade and would only make a line a little longer).
std::size_t columns(std::string_view text) {
    return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    }));
}

// The first `count` characters of displayable UTF-8 text.
std::string_view first_columns(std::string_view text, std::size_t count) {
    std::size_t at = 0;
    for (std::size_t seen = 0; at < text.size(); ++at) {
        if ((static_cast<unsigned char>(text[at]) & 0xC0) != 0x80 && seen++ == count) break;
    }
    return text.substr(0, at);
}

std::string pad_right(std::string text, std::size_t width) {
    const std::size_t used = columns(text);
    if (used < width) text.append(width - used, ' ');
    return text;
}

std::string pad_left(const std::string& text, std::size_t width) {
    const std::size_t used = columns(text);
    return used < width ? std::string(width - used, ' ') + text : text;
}

// The lines of displayable text, tabs as spaces, without the empty line after a final newline.
std::vector<std::string> lines_of(std::string_view text) {
    std::string shown = displayable_text(text);
    std::replace(shown.begin(), shown.end(), '\t', ' ');
    while (!shown.empty() && shown.back() == '\n')
        shown.pop_back();
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start <= shown.size()) {
        const std::size_t stop = std::min(shown.find('\n', start), shown.size());
        lines.push_back(shown.substr(start, stop - start));
        start = stop + 1;
    }
    return lines;
}

// Appends `text` after `prefix`, wrapped at kConsoleWidth with later lines indented by `indent`;
// a word wider than the room left on a line is broken.
void append_wrapped(std::string& out, const std::string& prefix, std::string_view text,
                    std::size_t indent) {
    std::string line = prefix;
    bool line_has_words = false;
    const auto end_line = [&] {
        while (!line.empty() && line.back() == ' ')
            line.pop_back();
        out += line + "\n";
        line = std::string(indent, ' ');
        line_has_words = false;
    };
    for (const std::string& paragraph : lines_of(text)) {
        std::string_view rest = paragraph;
        while (!rest.empty()) {
            const std::size_t space = std::min(rest.find(' '), rest.size());
            std::string_view word = rest.substr(0, space);
            rest.remove_prefix(std::min(space + 1, rest.size()));
            while (!word.empty()) {
                const std::size_t used = columns(line) + (line_has_words ? 1 : 0);
                const std::size_t room = kConsoleWidth > used ? kConsoleWidth - used : 0;
                if (columns(word) <= room) {
                    if (line_has_words) line += ' ';
                    line += word;
                    line_has_words = true;
                    break;
                }
                // Too wide: try a fresh line, and break the word only where even that is short.
                if (line_has_words || room == 0) {
                    end_line();
                    continue;
                }
                const std::string_view piece = first_columns(word, room);
                line += piece;
                word.remove_prefix(piece.size());
                line_has_words = true;
                end_line();
            }
        }
        end_line();
    }
}

// A check's visibility where the instructor's view shows it: nothing for visible checks.
std::string visibility_mark(Visibility visibility) {
    switch (visibility) {
        case Visibility::visible:
            return "";
        case Visibility::hidden:
            return " [hidden]";
        case Visibility::after_due_date:
            return " [after due date]";
        case Visibility::after_published:
            return " [after published]";
    }
    // Reached only by a value cast from outside the enum: visibility_name says so.
    return " [" + visibility_name(visibility) + "]";
}

// Under a check that did not pass: its first counterexample, or the first lines of its details.
void append_findings(std::string& out, const CheckResult& check, Audience audience) {
    const std::string indent(kFindingIndent, ' ');
    if (!check.counterexamples.empty()) {
        const Counterexample& example = check.counterexamples.front();
        const auto field = [&](std::string_view label, std::string_view value) {
            append_wrapped(out, indent + pad_right(std::string(label), 11),
                           clipped_text(value, kMaxFieldBytes), kFindingIndent + 11);
        };
        field("input", example.input);
        field("expected", example.expected);
        field("got", example.got);
        // Never wrapped: a command broken over two lines does not paste back as one.
        const std::string& command = reproduce_command(example, audience);
        if (!command.empty()) {
            out +=
                indent + pad_right("reproduce", 11) + clipped_text(command, kMaxFieldBytes) + "\n";
        }
        const std::size_t more = check.counterexamples.size() - 1;
        if (more > 0) {
            out += indent + "and " + std::to_string(more) + " more counterexample" +
                   (more == 1 ? "" : "s") + "\n";
        }
        return;
    }
    if (check.details.empty()) return;
    const std::vector<std::string> lines = lines_of(clipped_text(check.details, kMaxDetailsBytes));
    const std::size_t room = kConsoleWidth - kFindingIndent;
    for (std::size_t k = 0; k < lines.size() && k < kDetailLines; ++k) {
        // Cut rather than wrapped: a compiler's lines are long, and their starts say enough.
        const std::string& line = lines[k];
        out += indent +
               (columns(line) > room ? std::string(first_columns(line, room - 3)) + "..." : line) +
               "\n";
    }
    if (lines.size() > kDetailLines) {
        const std::size_t more = lines.size() - kDetailLines;
        out += indent + "(" + std::to_string(more) + " more line" + (more == 1 ? "" : "s") + ")\n";
    }
}

}  // namespace

std::string stage_table(const GradeReport& report) {
    // Rows: label, score, passed; the score column as wide as its widest entry.
    std::vector<std::vector<std::string>> rows = {{"stage", "score", "passed"}};
    for (const StageTally& tally : report.stage_tallies()) {
        rows.push_back({stage_label(tally.stage), score_out_of(tally.score, tally.max_score),
                        std::to_string(tally.passed) + " of " + std::to_string(tally.checks)});
    }
    const int all_passed = static_cast<int>(
        std::count_if(report.checks.begin(), report.checks.end(),
                      [](const CheckResult& check) { return check.outcome == Outcome::passed; }));
    rows.push_back({"total", score_out_of(report.score(), report.max_score()),
                    std::to_string(all_passed) + " of " + std::to_string(report.checks.size())});
    std::size_t score_width = 0;
    for (const auto& row : rows)
        score_width = std::max(score_width, columns(row[1]));
    std::string table;
    for (const auto& row : rows) {
        table +=
            "  " + pad_right(row[0], 10) + pad_left(row[1], score_width) + "   " + row[2] + "\n";
    }
    return table;
}

std::string console_summary(const GradeReport& report, Audience audience) {
    const GradeReport seen = seen_by(report, audience);
    std::string out;
    std::string who = report.student.empty() ? report.submission : report.student;
    if (!report.submission.empty() && report.submission != who)
        who += " (" + report.submission + ")";
    append_wrapped(out, "raystep-grade: ", who, kFindingIndent);
    const std::string intake_problem = intake_problem_line(report.intake_problem);
    if (!intake_problem.empty()) append_wrapped(out, "", intake_problem, 0);
    out += "Total: " + score_out_of(seen.score(), seen.max_score()) + " points\n\n";
    out += stage_table(seen);

    for (const int stage : kStageReportOrder) {
        bool first = true;
        for (const CheckResult& check : seen.checks) {
            if (check.stage != stage) continue;
            if (first) out += "\n" + stage_label(stage) + "\n";
            first = false;
            // "  failed          1.5 / 5  stage3.oracle.shared-edges: 97 of 100 cases right"
            const std::string head =
                std::string(kCheckIndent, ' ') + pad_right(outcome_name(check.outcome), 16) +
                pad_left(score_out_of(check.score, check.max_score), 10) + "  ";
            std::string line = check.id + visibility_mark(check.visibility);
            if (!check.summary.empty()) line += ": " + clipped_text(check.summary, kMaxFieldBytes);
            append_wrapped(out, head, line, columns(head));
            if (check.outcome != Outcome::passed) append_findings(out, check, audience);
        }
    }

    const std::size_t withheld = report.checks.size() - seen.checks.size();
    if (withheld > 0) {
        out += "\n";
        append_wrapped(out, "",
                       std::to_string(withheld) + (withheld == 1 ? " check is" : " checks are") +
                           " not shown here (hidden, or shown after the due date or once grades "
                           "are published); the scores above leave them out.",
                       0);
    }
    return out;
}

std::string console_paragraph(std::string_view text) {
    std::string out;
    append_wrapped(out, "", text, 0);
    return out;
}

}  // namespace raystep::grade
