#include "grader/report/check_findings.h"

#include <string_view>

#include "app/report/report_text.h"

namespace raystep::grade {

namespace {

// "  got:       value", continuation lines of a multi-line value indented under its first.
std::string field(std::string_view label, std::string_view value) {
    constexpr std::string_view kIndent = "             ";  // two spaces and the widest label
    std::string line = "  " + displayable_text(label) + ":";
    // Labels are ours and short; a long metric name gets one space instead of the column.
    line.append(line.size() < kIndent.size() ? kIndent.size() - line.size() : 1, ' ');
    for (const char c : clipped_text(value, kMaxFieldBytes)) {
        line += c;
        if (c == '\n') line += kIndent;
    }
    return line + "\n";
}

}  // namespace

std::string check_findings(const CheckResult& check, Audience audience, std::size_t max_bytes) {
    std::string text;
    const std::size_t count = check.counterexamples.size();
    for (std::size_t k = 0; k < count; ++k) {
        const Counterexample& example = check.counterexamples[k];
        if (!text.empty()) text += "\n";
        text += "Counterexample " + std::to_string(k + 1) + " of " + std::to_string(count) + "\n";
        text += field("input", example.input);
        text += field("expected", example.expected);
        text += field("got", example.got);
        const std::string& command = reproduce_command(example, audience);
        if (!command.empty()) text += field("reproduce", command);
    }
    if (!check.details.empty()) {
        if (!text.empty()) text += "\n";
        text += "Details\n" + clipped_text(check.details, kMaxDetailsBytes) + "\n";
    }
    if (!check.metrics.empty()) {
        if (!text.empty()) text += "\n";
        text += "Metrics\n";
        for (const auto& [name, value] : check.metrics) {
            text += field(name, metric_text(value));
        }
    }
    // The pieces are displayable already; this only enforces the budget.
    return clipped_text(text, max_bytes);
}

}  // namespace raystep::grade
