#pragma once

// Questions about a trace's lines (app/trace/trace_printer.h), for the tests that read one.

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace raystep::testing {

/// How many of `lines` begin with `start`.
inline std::size_t count_lines_starting(const std::vector<std::string>& lines,
                                        const std::string& start) {
    return static_cast<std::size_t>(
        std::count_if(lines.begin(), lines.end(),
                      [&](const std::string& line) { return line.rfind(start, 0) == 0; }));
}

/// Whether one of `lines` begins with `start`.
inline bool has_line_starting(const std::vector<std::string>& lines, const std::string& start) {
    return count_lines_starting(lines, start) > 0;
}

}  // namespace raystep::testing
