#pragma once

// How case files, scoring details and reports spell the values of a ray case: numbers with every
// digit (so a counterexample can be pasted back and rerun bit for bit) and shapes by their
// keyword. Private to app/check and the check command.

#include <cstdio>
#include <string>
#include <variant>

#include "app/check/ray_case.h"

namespace raystep {

/// The double with 17 significant digits, which reads back as the same bits: `0.10000000000000001`,
/// `-0`, `inf`, `nan`.
inline std::string exact_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

/// `(x, y, z)`, each with 17 significant digits.
inline std::string exact_text(const Vec3& v) {
    return "(" + exact_text(v.x) + ", " + exact_text(v.y) + ", " + exact_text(v.z) + ")";
}

/// The shape's keyword in case files and its name in reports: "sphere", "triangle" or "plane".
inline const char* shape_name(const CaseShape& shape) {
    if (std::holds_alternative<Sphere>(shape)) return "sphere";
    if (std::holds_alternative<Triangle>(shape)) return "triangle";
    return "plane";
}

}  // namespace raystep
