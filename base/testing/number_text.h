#pragma once

// How tests print numbers in their messages. Catch2 prints a double in fixed notation, 10 or 17
// digits after the point (Catch2 2 and 3.4 print 10, 3.7 prints 17): 1e-15 comes out as "0.0" and
// 1.3e201 as 202 digits. These print the value itself, so that a failure reads at a glance and can
// be pasted back into a test.

#include <cstdio>
#include <cstdlib>
#include <string>

#include "base/math/types.h"

namespace raystep::testing {

/// The shortest of %.15g, %.16g and %.17g that reads back as exactly `value`: `0.1`, `1e-15`,
/// `1.3e+201`, `0.10000000000000002`, `inf`, `nan`.
inline std::string exact_text(double value) {
    char text[32];
    for (const int digits : {15, 16}) {
        std::snprintf(text, sizeof text, "%.*g", digits, value);
        if (std::strtod(text, nullptr) == value) return text;  // false for NaN: %.17g prints it
    }
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

/// `(1, 0.5, -2e-09)`, each coordinate as exact_text writes it.
inline std::string exact_text(const Vec3& v) {
    return "(" + exact_text(v.x) + ", " + exact_text(v.y) + ", " + exact_text(v.z) + ")";
}

/// A tolerance or a margin, to 3 significant digits: what matters is its size. `1e-15`, `0.25`.
inline std::string size_text(double tolerance) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", tolerance);
    return text;
}

}  // namespace raystep::testing
