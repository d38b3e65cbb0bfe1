#include "grader/report/markup_escape.h"

#include "app/report/report_text.h"

namespace raystep::grade {

namespace {

std::string escaped(std::string_view text, bool in_attribute) {
    const std::string shown = displayable_text(text);
    std::string markup;
    markup.reserve(shown.size() + shown.size() / 8);
    for (const char c : shown) {
        switch (c) {
            case '&':
                markup += "&amp;";
                break;
            case '<':
                markup += "&lt;";
                break;
            case '>':
                markup += "&gt;";
                break;
            case '"':
                markup += "&quot;";
                break;
            // &apos; is XML's and HTML5's but not HTML 4's: the numeric form is read by all.
            case '\'':
                markup += "&#39;";
                break;
            case '\t':
                markup += in_attribute ? "&#9;" : "\t";
                break;
            case '\n':
                markup += in_attribute ? "&#10;" : "\n";
                break;
            default:
                markup += c;
        }
    }
    return markup;
}

}  // namespace

std::string markup_text(std::string_view text) {
    return escaped(text, false);
}

std::string markup_attribute(std::string_view text) {
    return escaped(text, true);
}

}  // namespace raystep::grade
