#pragma once

#include <filesystem>

#include "base/image/image.h"

namespace raystep {

/// Writes the image in the format its extension names, through OpenImageIO: 8-bit formats
/// (.png, .jpg, .ppm, ...) clamp to [0, 1] and round, with no gamma curve, as the CSE167
/// reference images do; .exr keeps the floats. Creates missing parent folders. Throws
/// std::runtime_error naming the file when it cannot be written.
void write_image(const Image& image, const std::filesystem::path& path);

/// Reads any image OpenImageIO can, as linear RGB floats (grey is spread to RGB, alpha is
/// dropped). Throws std::runtime_error naming the file when it cannot be read.
Image read_image(const std::filesystem::path& path);

}  // namespace raystep
