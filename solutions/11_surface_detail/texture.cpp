// Stage 11 reference solution: reading an image at texture coordinates.

#include <algorithm>
#include <cmath>

#include "stages/11_surface_detail/surface_detail.h"

namespace raystep {

int wrap_texel(int i, int size, WrapMode wrap) {
    switch (wrap) {
        case WrapMode::repeat:
            return ((i % size) + size) % size;
        case WrapMode::clamp:
            return std::clamp(i, 0, size - 1);
        case WrapMode::mirror: {
            const int k = ((i % (2 * size)) + 2 * size) % (2 * size);
            return k < size ? k : 2 * size - 1 - k;
        }
    }
    return 0;
}

Color texture_nearest(const Image& image, const Vec2& uv, WrapMode wrap) {
    const int i = static_cast<int>(std::floor(uv.x * image.width()));
    const int j = static_cast<int>(std::floor((1.0 - uv.y) * image.height()));
    return image.at(wrap_texel(i, image.width(), wrap), wrap_texel(j, image.height(), wrap));
}

Color texture_bilinear(const Image& image, const Vec2& uv, WrapMode wrap) {
    const double x = uv.x * image.width() - 0.5;
    const double y = (1.0 - uv.y) * image.height() - 0.5;
    const double x0 = std::floor(x);
    const double y0 = std::floor(y);
    const double fx = x - x0;
    const double fy = y - y0;
    const int i0 = wrap_texel(static_cast<int>(x0), image.width(), wrap);
    const int i1 = wrap_texel(static_cast<int>(x0) + 1, image.width(), wrap);
    const int j0 = wrap_texel(static_cast<int>(y0), image.height(), wrap);
    const int j1 = wrap_texel(static_cast<int>(y0) + 1, image.height(), wrap);
    return (1.0 - fx) * (1.0 - fy) * image.at(i0, j0) + fx * (1.0 - fy) * image.at(i1, j0) +
           (1.0 - fx) * fy * image.at(i0, j1) + fx * fy * image.at(i1, j1);
}

}  // namespace raystep
