#pragma once

#include <string>

namespace raystep::testing {

/// The line a test adds to its failures when the function it tests calls other functions the
/// student writes, or is held against one: a bug there fails this test too, and their own tests
/// show it more plainly. `INFO(uses("orthonormal_frame", "cross, length and normalize"))` prints
/// "orthonormal_frame uses cross, length and normalize: fix their failures first". One line, so
/// that it costs one line of each failure.
inline std::string uses(const std::string& function, const std::string& others) {
    return function + " uses " + others + ": fix their failures first";
}

}  // namespace raystep::testing
