// Stage 11: reading an image at texture coordinates. Handout: docs/stage11.md.

#include "base/errors/not_implemented.h"
#include "stages/11_surface_detail/surface_detail.h"

namespace raystep {

int wrap_texel(int i, int size, WrapMode wrap) {
    // C++'s % keeps the sign of i: -1 % 4 is -1, not 3.
    RAYSTEP_TODO(11, "wrap_texel", "Wrapping");
}

Color texture_nearest(const Image& image, const Vec2& uv, WrapMode wrap) {
    // Column floor(u W), row floor((1 - v) H): v = 0 is the bottom row, and row 0 is the top.
    RAYSTEP_TODO(11, "texture_nearest", "Texture lookup");
}

Color texture_bilinear(const Image& image, const Vec2& uv, WrapMode wrap) {
    // x = u W - 0.5, y = (1 - v) H - 0.5: the texel centres sit at whole x and y. Blend the four
    // texels around (x, y) by how near each is.
    RAYSTEP_TODO(11, "texture_bilinear", "Bilinear filtering");
}

}  // namespace raystep
