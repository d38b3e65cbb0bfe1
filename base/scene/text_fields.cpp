#include "base/scene/text_fields.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "base/errors/input_error.h"

namespace raystep {

namespace {

constexpr std::size_t kLongestQuotedField = 40;

// White space as isspace sees it in the "C" locale, without a call per character: a mesh file has
// millions of characters.
bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

[[noreturn]] void bad(const TextPosition& where, std::string_view what, std::string_view token,
                      std::string_view problem) {
    throw InputError(where.file, where.line,
                     std::string(what) + " " + quoted_field(token) + " " + std::string(problem));
}

}  // namespace

std::string quoted_field(std::string_view field) {
    std::string text = "'";
    for (std::size_t k = 0; k < field.size() && k < kLongestQuotedField; ++k) {
        const auto c = static_cast<unsigned char>(field[k]);
        if (c < 0x20 || c == 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
            text += escaped;
        } else {
            text += static_cast<char>(c);
        }
    }
    if (field.size() > kLongestQuotedField) text += "...";
    return text + "'";
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
            diagonal = above;
        }
    }
    return row[b.size()];
}

void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
    fields.clear();
    const std::size_t comment = line.find('#');
    if (comment != std::string_view::npos) line = line.substr(0, comment);
    std::size_t k = 0;
    while (k < line.size()) {
        while (k < line.size() && is_blank(line[k]))
            ++k;
        const std::size_t start = k;
        while (k < line.size() && !is_blank(line[k]))
            ++k;
        if (k > start) fields.push_back(line.substr(start, k - start));
    }
}

// Tokens are views into a line held in a std::string, so the character after a token is white
// space, '#', '\r' or the terminating NUL: strtod and strtol stop there, and checking that they
// stopped exactly at the token's end rejects "1.5x" and "2,5".

// Each parse tries std::from_chars first: it reads a plain decimal number as strtod does (doubles
// correctly rounded), several times faster, which is most of the time of loading a mesh of a
// hundred thousand faces. What it does not read whole ('+1', hexadecimal, a number out of range)
// goes on to strtod and strtol, whose rules and messages stand. libc++ before LLVM 20 (every
// Xcode so far) has no from_chars for double and leaves __cpp_lib_to_chars undefined: there the
// number goes straight to strtod, which gives the same double, only slower.
double parse_finite_number(std::string_view token, const TextPosition& where,
                           std::string_view what) {
#if defined(__cpp_lib_to_chars)
    double fast = 0.0;
    const auto [fast_end, fast_error] =
        std::from_chars(token.data(), token.data() + token.size(), fast);
    if (fast_error == std::errc() && fast_end == token.data() + token.size() &&
        std::isfinite(fast)) {
        return fast;
    }
#endif
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(token.data(), &end);
    if (end != token.data() + token.size() || token.empty())
        bad(where, what, token, "is not a number");
    if (std::isnan(value) || std::isinf(value)) {
        bad(where, what, token, errno == ERANGE ? "is too large for a double" : "is not finite");
    }
    return value;
}

long parse_count(std::string_view token, const TextPosition& where, std::string_view what) {
    long fast = 0;
    const auto [fast_end, fast_error] =
        std::from_chars(token.data(), token.data() + token.size(), fast);
    if (fast_error == std::errc() && fast_end == token.data() + token.size() && fast >= 0) {
        return fast;
    }
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(token.data(), &end, 10);
    if (end != token.data() + token.size() || token.empty()) {
        bad(where, what, token, "is not a whole number");
    }
    if (errno == ERANGE) bad(where, what, token, "is too large");
    if (value < 0) bad(where, what, token, "must not be negative");
    return value;
}

// from_chars reads digits only: no sign, no white space, no hexadecimal, so "-1" is refused rather
// than wrapped to 2^64 - 1 as strtoull would.
std::uint64_t parse_unsigned64(std::string_view token, const TextPosition& where,
                               std::string_view what) {
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error == std::errc::result_out_of_range) {
        bad(where, what, token, "is above 18446744073709551615, the largest 64-bit number");
    }
    if (error != std::errc() || end != token.data() + token.size() || token.empty()) {
        bad(where, what, token, "is not a whole number from 0 to 18446744073709551615");
    }
    return value;
}

}  // namespace raystep
