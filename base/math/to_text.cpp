#include "base/math/to_text.h"

#include <cstdio>

namespace raystep {

std::string to_text(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

std::string to_text(const Vec3& v) {
    return "(" + to_text(v.x) + ", " + to_text(v.y) + ", " + to_text(v.z) + ")";
}

}  // namespace raystep
