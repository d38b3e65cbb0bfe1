#include "studies/common/number_text.h"

#include <cmath>
#include <cstdio>

namespace raystep {

std::string grouped(std::size_t n) {
    std::string digits = std::to_string(n);
    for (std::size_t k = digits.size(); k > 3; k -= 3)
        digits.insert(k - 3, ",");
    return digits;
}

std::string fixed(double x, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, x);
    return text;
}

std::string three_digits(double x) {
    // Digits after the point: 3 minus the digits before it, never fewer than none
    const double magnitude = std::abs(x);
    int decimals = 2;
    if (magnitude >= 100.0) {
        decimals = 0;
    } else if (magnitude >= 10.0) {
        decimals = 1;
    } else if (magnitude > 0.0 && magnitude < 1.0) {
        decimals = 2 - static_cast<int>(std::floor(std::log10(magnitude)));
    }
    return fixed(x, decimals);
}

}  // namespace raystep
