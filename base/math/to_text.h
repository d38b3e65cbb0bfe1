#pragma once

#include <string>

#include "base/math/types.h"

namespace raystep {

// Numbers as messages and traces print them: 6 significant digits, enough to tell values apart
// when reading, and stable across platforms so that two traces of the same numbers compare
// equal line by line.

/// `1.5`, `-2e-09`, `inf`.
std::string to_text(double value);

/// `(1, 2.5, -3)`.
std::string to_text(const Vec3& v);

}  // namespace raystep
