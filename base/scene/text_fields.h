#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// Where a token came from, so that a bad one is reported as `file:line: ...`.
struct TextPosition {
    const std::string& file;
    int line;
};

/// Splits a line of text into its white-space separated fields, dropping everything from '#'
/// on (a comment) and a trailing '\r' (files written on Windows). The views point into `line`.
void split_fields(std::string_view line, std::vector<std::string_view>& fields);

/// A field as an error message shows it: in single quotes, control characters escaped as \xNN,
/// and cut to 40 characters and "..." so that a 2 MB token does not flood the terminal.
std::string quoted_field(std::string_view field);

/// The Levenshtein distance: how many one-character edits turn a into b.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The finite double that the whole token spells. Throws InputError at `where` when the token
/// is not a number, has trailing characters, overflows, or is inf or nan; `what` names the field
/// in the message ("the radius"). Underflow to zero or a subnormal is accepted: it is the
/// nearest double to what was written.
double parse_finite_number(std::string_view token, const TextPosition& where,
                           std::string_view what);

/// The non-negative whole number that the whole token spells; throws InputError like
/// parse_finite_number, also for a negative value or one that does not fit in a long.
long parse_count(std::string_view token, const TextPosition& where, std::string_view what);

/// The unsigned 64-bit whole number (0 to 2^64 - 1) that the whole token spells, in decimal;
/// throws InputError like parse_count, also for a sign or a value above 2^64 - 1.
std::uint64_t parse_unsigned64(std::string_view token, const TextPosition& where,
                               std::string_view what);

}  // namespace raystep
