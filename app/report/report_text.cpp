#include "app/report/report_text.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <utility>

namespace raystep::grade {

namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD in UTF-8

bool is_continuation(unsigned char byte) {
    return (byte & 0xC0) == 0x80;
}

// The code point of the valid UTF-8 sequence at text[at], and its length; length 0 when the bytes
// there are not one (a stray continuation byte, a truncated sequence, an overlong form, a
// surrogate, or a value past U+10FFFF). RFC 3629, section 4.
std::pair<std::uint32_t, std::size_t> decode_utf8(std::string_view text, std::size_t at) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[at + k]); };
    const unsigned char lead = byte(0);
    if (lead < 0x80) return {lead, 1};
    std::size_t length = 0;
    std::uint32_t code = 0;
    // The smallest second byte of each lead that rules out overlong forms and surrogates, and the
    // largest that rules out surrogates and values past U+10FFFF.
    unsigned char second_min = 0x80;
    unsigned char second_max = 0xBF;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
        code = lead & 0x1Fu;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        code = lead & 0x0Fu;
        if (lead == 0xE0) second_min = 0xA0;
        if (lead == 0xED) second_max = 0x9F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        code = lead & 0x07u;
        if (lead == 0xF0) second_min = 0x90;
        if (lead == 0xF4) second_max = 0x8F;
    } else {
        return {0, 0};
    }
    if (at + length > text.size()) return {0, 0};
    if (byte(1) < second_min || byte(1) > second_max) return {0, 0};
    for (std::size_t k = 1; k < length; ++k) {
        if (!is_continuation(byte(k))) return {0, 0};
        code = (code << 6) | (byte(k) & 0x3Fu);
    }
    return {code, length};
}

// Characters that act on a reader instead of showing: see displayable_text.
bool acts_on_reader(std::uint32_t code) {
    if (code == '\t' || code == '\n') return false;
    const bool control = code < 0x20 || (code >= 0x7F && code <= 0x9F);
    const bool bidi = (code >= 0x202A && code <= 0x202E) || (code >= 0x2066 && code <= 0x2069);
    const bool not_xml = code == 0xFFFE || code == 0xFFFF;
    return control || bidi || not_xml;
}

// Appends the displayable form of the text's start to `shown`, stopping before a character that
// would take `shown` past max_bytes; returns how many bytes of the text it consumed.
std::size_t append_displayable(std::string_view text, std::size_t max_bytes, std::string& shown) {
    std::size_t at = 0;
    while (at < text.size()) {
        const auto [code, length] = decode_utf8(text, at);
        std::string_view piece;
        std::size_t consumed = length;
        if (length == 0) {
            // Not UTF-8: one replacement per byte, so the reader can see how much was lost.
            piece = kReplacement;
            consumed = 1;
        } else if (code == '\r' && at + 1 < text.size() && text[at + 1] == '\n') {
            // Windows line ends read as line ends: the carriage return goes.
        } else if (acts_on_reader(code)) {
            piece = kReplacement;
        } else {
            piece = text.substr(at, length);
        }
        if (shown.size() + piece.size() > max_bytes) break;
        shown.append(piece);
        at += consumed;
    }
    return at;
}

}  // namespace

std::string displayable_text(std::string_view text) {
    std::string shown;
    shown.reserve(text.size());
    append_displayable(text, text.size() * kReplacement.size(), shown);
    return shown;
}

std::string clipped_text(std::string_view text, std::size_t max_bytes) {
    // Only what is shown is made displayable: a submission's output may be megabytes.
    std::string shown;
    const std::size_t consumed = append_displayable(text, max_bytes, shown);
    if (consumed < text.size()) {
        shown += " [... " + std::to_string(text.size() - consumed) + " more bytes]";
    }
    return shown;
}

std::string score_text(double score) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.2f", score);
    std::string text = buffer;
    if (text.find('.') != std::string::npos) {
        while (text.back() == '0')
            text.pop_back();
        if (text.back() == '.') text.pop_back();
    }
    // A score rounded to zero from below reads as "-0".
    if (text == "-0") text = "0";
    return text;
}

std::string score_below_max_text(double score, double max_score) {
    // A check is passed only at full points (scored_check, app/grade/rubric.h): a score short of
    // its maximum that two decimals would round up to it is cut to two decimals instead, so that
    // a failed 0.998 reads "0.99 / 1", never "failed 1 / 1", and a total of 20.998 never "21".
    const std::string shown = score_text(score);
    if (score < max_score && shown == score_text(max_score)) {
        return score_text(std::floor(score * 100) / 100);
    }
    return shown;
}

std::string score_out_of(double score, double max_score) {
    return score_below_max_text(score, max_score) + " / " + score_text(max_score);
}

std::string metric_text(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.4g", value);
    return buffer;
}

std::string stage_label(int stage) {
    return stage == 0 ? "pipeline" : "stage " + std::to_string(stage);
}

std::string intake_problem_line(std::string_view problem) {
    if (problem.empty()) return "";
    return "The submission's files could not all be taken: " +
           clipped_text(problem, kMaxFieldBytes);
}

}  // namespace raystep::grade
