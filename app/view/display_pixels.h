#pragma once

#include <string>

#include "base/image/image.h"
#include "renderer/tile_renderer.h"

namespace raystep {

/// Appends the pixels of `tile` of `image` to `bytes` as the browser's canvas takes them: red,
/// green, blue and alpha (255) per pixel, row by row from the top, each channel the linear value
/// clamped to [0, 1] and rounded to the nearest of 0..255, as OpenImageIO writes a PNG. A pixel
/// in `raystep view` is so the byte that `raystep render` writes; NaN shows as 0.
void append_display_pixels(const Image& image, const TileRect& tile, std::string& bytes);

}  // namespace raystep
