#include "core/scene/text_fields.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/errors/input_error.h"

namespace raystep {

namespace {

[[noreturn]] void bad(const TextPosition& where, std::string_view what, std::string_view token,
                      std::string_view problem) {
    throw InputError(where.file, where.line,
                     std::string(what) + " '" + std::string(token) + "' " + std::string(problem));
}

}  // namespace

void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
    fields.clear();
    const std::size_t comment = line.find('#');
    if (comment != std::string_view::npos) line = line.substr(0, comment);
    std::size_t k = 0;
    while (k < line.size()) {
        while (k < line.size() && std::isspace(static_cast<unsigned char>(line[k])))
            ++k;
        const std::size_t start = k;
        while (k < line.size() && !std::isspace(static_cast<unsigned char>(line[k])))
            ++k;
        if (k > start) fields.push_back(line.substr(start, k - start));
    }
}

// Tokens are views into a line held in a std::string, so the character after a token is white
// space, '#', '\r' or the terminating NUL: strtod and strtol stop there, and checking that they
// stopped exactly at the token's end rejects "1.5x" and "2,5".

double parse_finite_number(std::string_view token, const TextPosition& where,
                           std::string_view what) {
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

}  // namespace raystep
