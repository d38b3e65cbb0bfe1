#pragma once

#include <string>

#include "base/math/types.h"

namespace raystep::grade {

// How a case's values are written in a report, the same way for every check and for
// `raystep grade`: every digit (17 significant), so that a counterexample shows the difference,
// however small, and can be typed back in.

/// `1.0000000000000002`, `inf`.
std::string full_text(double x);

/// `(1, 2.5, -3)`, each coordinate as full_text writes it.
std::string full_text(const Vec3& v);

}  // namespace raystep::grade
