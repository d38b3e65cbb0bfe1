// Stage 11: reading an image at texture coordinates. Handout: docs/stage11.md.

#include <cmath>

#include "stages/11_surface_detail/surface_detail.h"

namespace raystep {

int wrap_texel(int i, int size, WrapMode wrap) {
    if (wrap == WrapMode::clamp) {
        if (i < 0) return 0;
        if (i >= size) return size - 1;
        return i;
    }
    if (wrap == WrapMode::repeat) {
        const int r = i % size;
        return r < 0 ? r + size : r;
    }
    // Mirror: every other copy of the image runs backwards.
    int r = i % (2 * size);
    if (r < 0) r += 2 * size;
    return r < size ? r : 2 * size - 1 - r;
}

Color texture_nearest(const Image& image, const Vec2& uv, WrapMode wrap) {
    const int w = image.width();
    const int h = image.height();
    const int column = static_cast<int>(std::floor(uv.x * w));
    const int row = static_cast<int>(std::floor((1.0 - uv.y) * h));
    return image.at(wrap_texel(column, w, wrap), wrap_texel(row, h, wrap));
}

Color texture_bilinear(const Image& image, const Vec2& uv, WrapMode wrap) {
    const int w = image.width();
    const int h = image.height();
    const double x = uv.x * w - 0.5;
    const double y = (1.0 - uv.y) * h - 0.5;
    const int i = static_cast<int>(std::floor(x));
    const int j = static_cast<int>(std::floor(y));
    const double fx = x - i;
    const double fy = y - j;
    const auto texel = [&](int di, int dj) {
        return image.at(wrap_texel(i + di, w, wrap), wrap_texel(j + dj, h, wrap));
    };
    const Color top = texel(0, 0) + fx * (texel(1, 0) - texel(0, 0));
    const Color bottom = texel(0, 1) + fx * (texel(1, 1) - texel(0, 1));
    return top + fy * (bottom - top);
}

}  // namespace raystep
