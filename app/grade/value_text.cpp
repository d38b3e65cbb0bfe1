#include "app/grade/value_text.h"

#include <cstdio>

namespace raystep::grade {

std::string full_text(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

std::string full_text(const Vec3& v) {
    return "(" + full_text(v.x) + ", " + full_text(v.y) + ", " + full_text(v.z) + ")";
}

}  // namespace raystep::grade
