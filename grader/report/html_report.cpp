#include "grader/report/html_report.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>

#include "app/report/report_text.h"
#include "grader/report/data_url.h"
#include "grader/report/html_style.h"
#include "grader/report/markup_escape.h"

namespace raystep::grade {

namespace {

// Scripts, frames, fonts and fetches are refused even if something slipped past the escaping.
// A self-contained page shows only the images inside it; the other may show files beside it
// (file: when opened from disk).
constexpr std::string_view kSelfContainedPolicy =
    "default-src 'none'; img-src data:; style-src 'unsafe-inline'";
constexpr std::string_view kLinkedImagesPolicy =
    "default-src 'none'; img-src 'self' file: data:; style-src 'unsafe-inline'";

// An image larger than this is shown as missing rather than carried inside the page: a render
// check's PNG is tens of kilobytes.
constexpr std::size_t kMaxEmbeddedImageBytes = 4u << 20;

std::string h(std::string_view text) {
    return markup_text(text);
}
std::string attr(std::string_view text) {
    return markup_attribute(text);
}

// "outcome-name" as a CSS class: "timed-out", "did-not-compile".
std::string outcome_class(Outcome outcome) {
    std::string name = outcome_name(outcome);
    std::replace(name.begin(), name.end(), ' ', '-');
    return name;
}

std::string stage_anchor(int stage) {
    return "stage-" + std::to_string(stage);
}

// A relative path as a URL path: every byte but the unreserved ones and '/' percent-encoded
// (RFC 3986, section 2), so a '#', '?' or space in a file name stays part of the path.
std::string url_path(const std::string& path) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string url;
    for (const char c : path) {
        const auto byte = static_cast<unsigned char>(c);
        const bool unreserved = (byte >= 'A' && byte <= 'Z') || (byte >= 'a' && byte <= 'z') ||
                                (byte >= '0' && byte <= '9') || c == '-' || c == '.' || c == '_' ||
                                c == '~' || c == '/';
        if (unreserved) {
            url += c;
        } else {
            url += '%';
            url += kHex[byte >> 4];
            url += kHex[byte & 0x0F];
        }
    }
    return url;
}

std::string percent(double score, double max_score) {
    if (!(max_score > 0.0)) return "0";  // also rejects a NaN maximum
    const double share = std::clamp(score / max_score, 0.0, 1.0);
    return std::to_string(static_cast<int>(std::lround(100.0 * share)));
}

std::string page_head(const GradeReport& seen, const HtmlReportOptions& options) {
    const std::string who = seen.student.empty() ? seen.submission : seen.student;
    std::string html =
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\" />\n"
        "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\" />\n"
        "<meta http-equiv=\"Content-Security-Policy\" content=\"" +
        std::string(options.self_contained ? kSelfContainedPolicy : kLinkedImagesPolicy) +
        "\" />\n<title>raystep grade: " + h(who) + ", " +
        h(score_out_of(seen.score(), seen.max_score())) + "</title>\n<style>" +
        std::string(html_style()) + "</style>\n</head>\n<body>\n";
    html += "<header class=\"page-head\"><div class=\"inner\">\n<div class=\"who\"><h1>" + h(who) +
            "</h1>\n";
    if (!seen.submission.empty() && seen.submission != who) {
        html += "<div class=\"submission\">" + h(seen.submission) + "</div>\n";
    }
    html += "<div class=\"submission\">raystep grade report, " +
            std::string(options.audience == Audience::instructor ? "instructor's view"
                                                                 : "student's view") +
            "</div></div>\n<div class=\"total\">" +
            h(score_below_max_text(seen.score(), seen.max_score())) + " <small>/ " +
            h(score_text(seen.max_score())) + " points (" +
            percent(seen.score(), seen.max_score()) + "%)</small></div>\n</div></header>\n<main>\n";
    return html;
}

std::string stage_scores(const GradeReport& seen) {
    std::string rows;
    for (const StageTally& t : seen.stage_tallies()) {
        rows += "<tr><td><a href=\"#" + stage_anchor(t.stage) + "\">" + h(stage_label(t.stage)) +
                "</a></td><td class=\"num\">" + h(score_out_of(t.score, t.max_score)) +
                "</td><td class=\"num\">" + std::to_string(t.passed) + " of " +
                std::to_string(t.checks) + "</td><td><span class=\"bar\"><span style=\"width: " +
                percent(t.score, t.max_score) + "%\"></span></span></td></tr>\n";
    }
    const auto all_passed =
        std::count_if(seen.checks.begin(), seen.checks.end(),
                      [](const CheckResult& c) { return c.outcome == Outcome::passed; });
    return "<section><h2>Scores per stage</h2>\n<table class=\"scores\">\n<thead><tr><th>Stage</th>"
           "<th class=\"num\">Score</th><th class=\"num\">Checks passed</th><th>Share</th></tr>"
           "</thead>\n<tbody>\n" +
           rows + "</tbody>\n<tfoot><tr><th>Total</th><td class=\"num\">" +
           h(score_out_of(seen.score(), seen.max_score())) + "</td><td class=\"num\">" +
           std::to_string(all_passed) + " of " + std::to_string(seen.checks.size()) +
           "</td><td><span class=\"bar\"><span style=\"width: " +
           percent(seen.score(), seen.max_score()) +
           "%\"></span></span></td></tr></tfoot>\n</table>\n</section>\n";
}

std::string metrics_table(const CheckResult& check) {
    if (check.metrics.empty()) return "";
    std::string names;
    std::string values;
    for (const auto& [name, value] : check.metrics) {
        names += "<th class=\"num\">" + h(name) + "</th>";
        values += "<td class=\"num\">" + h(metric_text(value)) + "</td>";
    }
    return "<table class=\"metrics\"><tr>" + names + "</tr><tr>" + values + "</tr></table>\n";
}

// The image's source: its data URL for a self-contained page, else its path as a relative URL;
// nullopt when the file is missing.
std::optional<std::string> image_source(const std::filesystem::path& folder,
                                        const std::string& path, bool self_contained) {
    if (self_contained) return image_data_url(folder / path, kMaxEmbeddedImageBytes);
    if (!std::filesystem::exists(folder / path)) return std::nullopt;
    return url_path(path);
}

std::string figure(const std::filesystem::path& folder, const std::string& path,
                   const std::string& caption, bool self_contained) {
    if (path.empty()) return "";
    std::string shown;
    if (const std::optional<std::string> source = image_source(folder, path, self_contained)) {
        shown = "<img src=\"" + attr(*source) + "\" alt=\"" + attr(caption + " image") + "\" />";
    } else {
        shown = "<div class=\"missing-image\">missing: " + h(path) + "</div>";
    }
    return "<figure>" + shown + "<figcaption>" + h(caption) + "</figcaption></figure>";
}

std::string render_images(const std::filesystem::path& folder, const RenderImages& images,
                          bool self_contained) {
    const std::string figures = figure(folder, images.reference, "reference", self_contained) +
                                figure(folder, images.student, "student", self_contained) +
                                figure(folder, images.difference, "difference", self_contained);
    return figures.empty() ? "" : "<div class=\"images\">" + figures + "</div>\n";
}

std::string reproduce_row(const std::string& label, const std::string& command) {
    if (command.empty()) return "";
    return "<tr class=\"reproduce\"><td></td><td colspan=\"3\">" + h(label) + ": <code>" +
           h(clipped_text(command, kMaxFieldBytes)) + "</code></td></tr>\n";
}

std::string counterexamples_table(const CheckResult& check, Audience audience) {
    if (check.counterexamples.empty()) return "";
    std::string html =
        "<table class=\"counterexamples\"><thead><tr><th>#</th><th>Input</th><th>Expected</th>"
        "<th>Got</th></tr></thead>\n<tbody>\n";
    for (std::size_t k = 0; k < check.counterexamples.size(); ++k) {
        const Counterexample& example = check.counterexamples[k];
        html += "<tr><td>" + std::to_string(k + 1) + "</td><td>" +
                h(clipped_text(example.input, kMaxFieldBytes)) + "</td><td>" +
                h(clipped_text(example.expected, kMaxFieldBytes)) + "</td><td>" +
                h(clipped_text(example.got, kMaxFieldBytes)) + "</td></tr>\n";
        html += reproduce_row("reproduce", reproduce_command(example, audience));
        // The instructor also sees what the student's report tells them to run.
        if (audience == Audience::instructor) {
            html += reproduce_row("the student's command", example.student_reproduce);
        }
    }
    return html + "</tbody></table>\n";
}

std::string details_block(const CheckResult& check) {
    if (check.details.empty()) return "";
    // Open where the details are the finding itself: a compiler's errors, a crash, a timeout.
    const bool open = check.outcome == Outcome::did_not_compile ||
                      check.outcome == Outcome::crashed || check.outcome == Outcome::timed_out;
    const char* label = check.outcome == Outcome::did_not_compile ? "Compiler output" : "Details";
    return std::string("<details") + (open ? " open=\"open\"" : "") + "><summary>" + label +
           "</summary><pre>" + h(clipped_text(check.details, kMaxDetailsBytes)) +
           "</pre></details>\n";
}

std::string check_section(const CheckResult& check, int number,
                          const std::filesystem::path& images_folder,
                          const HtmlReportOptions& options) {
    const std::string outcome = outcome_class(check.outcome);
    std::string html =
        "<article class=\"check " + outcome + "\" id=\"check-" + std::to_string(number) +
        "\">\n<div class=\"check-head\"><span class=\"badge " + outcome + "\">" +
        h(outcome_name(check.outcome)) + "</span><h3>" +
        h(check.name.empty() ? check.id : check.name) + "</h3><span class=\"points\">" +
        h(score_out_of(check.score, check.max_score)) + "</span></div>\n";
    html += "<p class=\"meta\"><code>" + h(check.id) + "</code> &#183; " + h(check.kind);
    if (check.visibility != Visibility::visible) {
        html += " &#183; <span class=\"visibility\">" + h(visibility_name(check.visibility)) +
                "</span>";
    }
    html += "</p>\n";
    if (!check.summary.empty()) {
        html += "<p class=\"summary\">" + h(clipped_text(check.summary, kMaxFieldBytes)) + "</p>\n";
    }
    html += metrics_table(check) +
            render_images(images_folder, check.images, options.self_contained) +
            counterexamples_table(check, options.audience) + details_block(check);
    return html + "</article>\n";
}

std::string times_footer(const PhaseTimes& times) {
    const auto seconds = [](double s) { return metric_text(s) + " s"; };
    return "<footer>Graded by raystep-grade in " +
           seconds(times.intake + times.build + times.checks + times.reports) + ": intake " +
           seconds(times.intake) + ", build " + seconds(times.build) + ", checks " +
           seconds(times.checks) + ", reports " + seconds(times.reports) + ".</footer>\n";
}

}  // namespace

std::string html_report(const GradeReport& report, const std::filesystem::path& images_folder,
                        const HtmlReportOptions& options) {
    const GradeReport seen = seen_by(report, options.audience);
    std::string html = page_head(seen, options);

    const std::string intake_problem = intake_problem_line(report.intake_problem);
    if (!intake_problem.empty()) html += "<p class=\"problem\">" + h(intake_problem) + "</p>\n";

    const std::size_t withheld = report.checks.size() - seen.checks.size();
    if (withheld > 0) {
        html += "<p class=\"note\">" + std::to_string(withheld) +
                (withheld == 1 ? " check is" : " checks are") +
                " not shown here (hidden, or shown after the due date or once grades are "
                "published); the scores leave them out.</p>\n";
    }
    if (options.audience == Audience::instructor &&
        std::any_of(report.checks.begin(), report.checks.end(),
                    [](const CheckResult& c) { return c.visibility != Visibility::visible; })) {
        html +=
            "<p class=\"note\">Instructor's view: this page shows hidden checks. Give "
            "students the student's view.</p>\n";
    }
    html += stage_scores(seen);
    if (!options.speed_error_chart_svg.empty()) {
        html += "<section class=\"chart\" id=\"speed-versus-error\"><h2>Speed versus error</h2>\n" +
                options.speed_error_chart_svg + "\n</section>\n";
    }
    int number = 0;
    for (const int stage : kStageReportOrder) {
        std::string sections;
        for (const CheckResult& check : seen.checks) {
            if (check.stage == stage) {
                sections += check_section(check, ++number, images_folder, options);
            }
        }
        if (sections.empty()) continue;
        html += "<section id=\"" + stage_anchor(stage) + "\"><h2>" +
                h(stage == 0 ? "The whole pipeline" : "Stage " + std::to_string(stage)) +
                "</h2>\n" + sections + "</section>\n";
    }
    return html + times_footer(seen.times) + "</main>\n</body>\n</html>\n";
}

}  // namespace raystep::grade
