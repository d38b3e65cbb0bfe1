#include "app/view/display_pixels.h"

#include <cmath>

namespace raystep {

namespace {

char display_byte(float value) {
    if (!(value > 0.0f)) return 0;  // NaN too
    if (value >= 1.0f) return static_cast<char>(255);
    return static_cast<char>(static_cast<unsigned char>(std::floor(value * 255.0f + 0.5f)));
}

}  // namespace

void append_display_pixels(const Image& image, const TileRect& tile, std::string& bytes) {
    bytes.reserve(bytes.size() + 4 * static_cast<std::size_t>(tile.x1 - tile.x0) *
                                     static_cast<std::size_t>(tile.y1 - tile.y0));
    for (int j = tile.y0; j < tile.y1; ++j) {
        for (int i = tile.x0; i < tile.x1; ++i) {
            const Color c = image.at(i, j);
            bytes.push_back(display_byte(static_cast<float>(c.r)));
            bytes.push_back(display_byte(static_cast<float>(c.g)));
            bytes.push_back(display_byte(static_cast<float>(c.b)));
            bytes.push_back(static_cast<char>(255));
        }
    }
}

}  // namespace raystep
