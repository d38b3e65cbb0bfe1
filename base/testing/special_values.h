#pragma once

#include <limits>

namespace raystep::testing {

/// The non-finite doubles that hard cases feed to a function and that its answers are held to.
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace raystep::testing
