#pragma once

// How often a piece of text occurs in a study's output, for the tests that count marks in it.

#include <cstddef>
#include <string>

namespace raystep::testing {

/// The occurrences of `what` in `text`, overlapping ones included.
inline std::size_t occurrences(const std::string& text, const std::string& what) {
    std::size_t count = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++count;
    return count;
}

}  // namespace raystep::testing
