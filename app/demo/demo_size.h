#pragma once

#include <string>
#include <string_view>

namespace raystep {

/// The whole image a demo writes, in pixels.
struct DemoSize {
    int width = 640;
    int height = 480;
};

/// The smallest image `raystep demo --size` and the page take: below 240 rows a caption, drawn at
/// a 26th of the height (demo_figure.cpp), would fall under the 9 pixels that draw_text shrinks to.
constexpr DemoSize kSmallestDemoSize{320, 240};
/// The largest: a 4K (UHD) projector's image, 8.3 million pixels.
constexpr DemoSize kLargestDemoSize{3840, 2160};

/// WIDTHxHEIGHT ("1920x1080": two whole numbers in decimal digits, an 'x' between them) as a
/// DemoSize from kSmallestDemoSize to kLargestDemoSize. Throws std::invalid_argument saying what
/// is wrong with `text` and what it should be.
DemoSize parse_demo_size(std::string_view text);

/// "1920 x 1080".
std::string demo_size_text(const DemoSize& size);

}  // namespace raystep
