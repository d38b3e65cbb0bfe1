#pragma once

#include <cstdint>
#include <sstream>
#include <string>

namespace raystep::grade {

/// A size as the grader's budgets and notes say it, in mebibytes to three significant digits:
/// "64 MiB", "1.05 MiB", "0.5 MiB".
inline std::string mebibytes(std::uintmax_t bytes) {
    std::ostringstream text;
    text.precision(3);
    text << static_cast<double>(bytes) / (1 << 20) << " MiB";
    return text.str();
}

}  // namespace raystep::grade
