#include "app/demo/demo_size.h"

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace raystep {

namespace {

// The whole number `digits` spells, or -1 when it is not digits alone. One of more than nine
// digits, more than an int holds, is taken as the largest int: too large all the same.
int whole_number(std::string_view digits) {
    if (digits.empty()) return -1;
    long long value = 0;
    for (const char c : digits) {
        if (c < '0' || c > '9') return -1;
        value = std::min(10 * value + (c - '0'), static_cast<long long>(INT_MAX));
    }
    return static_cast<int>(value);
}

}  // namespace

DemoSize parse_demo_size(std::string_view text) {
    const std::string quoted = "'" + std::string(text) + "'";
    const std::string expected = "WIDTHxHEIGHT in pixels, such as 1920x1080";

    // Two numbers, one 'x' between them
    const std::size_t x = text.find_first_of("xX");
    if (x == std::string_view::npos) {
        throw std::invalid_argument(quoted + " has no 'x' between width and height: write " +
                                    expected);
    }
    const int width = whole_number(text.substr(0, x));
    const int height = whole_number(text.substr(x + 1));
    if (width < 0 || height < 0) {
        throw std::invalid_argument(
            quoted + " is not two whole numbers with an 'x' between: " + "write " + expected);
    }

    // Within the sizes a figure is drawn at
    const DemoSize size{width, height};
    const DemoSize& low = kSmallestDemoSize;
    const DemoSize& high = kLargestDemoSize;
    if (width < low.width || height < low.height) {
        throw std::invalid_argument(quoted + " is too small: a demo is at least " +
                                    demo_size_text(low) +
                                    ", where its captions are still 9 pixels high");
    }
    if (width > high.width || height > high.height) {
        throw std::invalid_argument(quoted + " is too large: a demo is at most " +
                                    demo_size_text(high) + " (a 4K projector's image)");
    }
    return size;
}

std::string demo_size_text(const DemoSize& size) {
    return std::to_string(size.width) + " x " + std::to_string(size.height);
}

}  // namespace raystep
