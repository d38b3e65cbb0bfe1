#pragma once

#include <filesystem>

#include "base/image/image.h"

namespace raystep {

/// Writes the image in the format its extension names, through OpenImageIO: 8-bit formats
/// (.png, .jpg, .ppm, ...) clamp to [0, 1] and round, with no gamma curve, as the CSE167
/// reference images do; .exr keeps the floats. Creates missing parent folders. Throws
/// std::runtime_error naming the file when it cannot be written, or naming the image library's
/// path when it cannot be loaded (base/image/image_library_loader.h: loaded on first use).
void write_image(const Image& image, const std::filesystem::path& path);

/// Reads any image OpenImageIO can, as linear RGB floats (grey is spread to RGB, alpha is
/// dropped). Throws std::runtime_error naming the file when it cannot be read.
Image read_image(const std::filesystem::path& path);

}  // namespace raystep
